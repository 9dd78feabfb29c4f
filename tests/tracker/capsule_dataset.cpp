#include "tests/tracker/capsule_dataset.h"

#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>

#include "core/calibration.h"
#include "core/image_io.h"
#include "core/joint_track.h"
#include "core/rig.h"
#include "models/humanoid.h"
#include "models/pose.h"

namespace simcap::testing {
namespace fs = std::filesystem;
namespace {

struct Capsule {
  Eigen::Vector3d a, b;
  double radius;
};

// Distance between the ray o + s d (s >= 0, |d| = 1) and the segment [a, b].
double ray_segment_distance(const Eigen::Vector3d& o, const Eigen::Vector3d& d, const Capsule& c) {
  const Eigen::Vector3d u = c.b - c.a, w = o - c.a;
  const double uu = u.dot(u), ud = u.dot(d), uw = u.dot(w), dw = d.dot(w);
  const double den = uu - ud * ud;
  double t = den > 1e-12 ? std::clamp((uw - ud * dw) / den, 0.0, 1.0) : 0.0;
  const double s = std::max(0.0, (c.a + t * u - o).dot(d));
  t = std::clamp((o + s * d - c.a).dot(u) / uu, 0.0, 1.0);
  return (o + s * d - c.a - t * u).norm();
}

double radius_of(const std::string& joint) {
  if (joint == "skull_tip") return 0.09;
  if (joint.find("hip") != std::string::npos) return 0.08;
  if (joint.find("knee") != std::string::npos) return 0.07;
  if (joint.find("talocrural") != std::string::npos) return 0.05;
  if (joint.find("elbow") != std::string::npos) return 0.045;
  if (joint.find("radiocarpal") != std::string::npos) return 0.04;
  if (joint.find("hand_tip") != std::string::npos) return 0.035;
  if (joint.find("toe") != std::string::npos || joint.find("metatarso") != std::string::npos) {
    return 0.04;
  }
  if (joint.find("shoulder") != std::string::npos) return 0.06;
  if (joint.find("sternoclavicular") != std::string::npos) return 0.06;
  if (joint == "vc4" || joint == "skullbase") return 0.05;
  return 0.12;  // spine
}

Pose pose_at(const Skeleton& s, int frame) {
  Pose p = Pose::neutral(s);
  const double phase = 0.5 * frame;
  p.root_position += Eigen::Vector3d(0.0, 0.0, 0.03 * frame);
  auto rot = [&](const char* joint, double angle, const Eigen::Vector3d& axis) {
    p.rotations[s.require(joint)] = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis));
  };
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Z = Eigen::Vector3d::UnitZ();
  rot("l_hip", -0.35 * std::sin(phase), X);
  rot("r_hip", 0.35 * std::sin(phase), X);
  rot("l_knee", 0.3 + 0.25 * std::cos(phase), X);
  rot("r_knee", 0.3 - 0.25 * std::cos(phase), X);
  rot("l_shoulder", 0.35, Z);
  rot("r_shoulder", -0.35, Z);
  rot("l_elbow", -0.6 - 0.3 * std::sin(phase), X);
  rot("r_elbow", -0.6 + 0.3 * std::sin(phase), X);
  return p;
}

cv::Vec3b plate_colour(int u, int v) {
  return cv::Vec3b(static_cast<std::uint8_t>(120 + (u * 7 + v * 3) % 40),
                   static_cast<std::uint8_t>(130 + (u * 3 + v * 5) % 30),
                   static_cast<std::uint8_t>(110 + (u + v) % 50));
}

}  // namespace

void write_capsule_dataset(const fs::path& root, const CapsuleDatasetSpec& spec) {
  const Skeleton skeleton = build_humanoid();
  const std::vector<Camera> cams =
      ring_rig(spec.cameras, {0.0, 0.9, 0.1}, 3.0, 2.0, {spec.width, spec.height, 1.05});
  write_opencv_calibration(root / "calibration" / "opencv.yaml", cams);
  for (const Camera& cam : cams) {
    cv::Mat plate(cam.height, cam.width, CV_8UC3);
    for (int v = 0; v < cam.height; ++v)
      for (int u = 0; u < cam.width; ++u) plate.at<cv::Vec3b>(v, u) = plate_colour(u, v);
    write_image(root / "background" / (cam.name + ".png"), plate);
  }
  JointTrack gt;
  for (const Joint& j : skeleton.joints()) {
    if (!j.is_site) gt.joints.push_back(j.name);
  }
  for (int f = 0; f < spec.frames; ++f) {
    const auto positions = joint_positions(skeleton, pose_at(skeleton, f));
    std::vector<Capsule> capsules;
    std::vector<Eigen::Vector3d> row;
    for (int j = 0; j < skeleton.size(); ++j) {
      if (!skeleton[j].is_site) row.push_back(positions[j]);
      const int p = skeleton[j].parent;
      if (p >= 0) capsules.push_back({positions[p], positions[j], radius_of(skeleton[j].name)});
    }
    gt.add_frame(f, row);
    char name[16];
    std::snprintf(name, sizeof name, "%06d.png", f);
    for (const Camera& cam : cams) {
      cv::Mat mask(cam.height, cam.width, CV_8UC1, cv::Scalar(0));
      cv::Mat rgb(cam.height, cam.width, CV_8UC3);
      const Eigen::Vector3d o = cam.centre();
      for (int v = 0; v < cam.height; ++v) {
        for (int u = 0; u < cam.width; ++u) {
          const Eigen::Vector3d d = cam.unproject({u, v});
          bool hit = false;
          for (const Capsule& c : capsules) {
            if (ray_segment_distance(o, d, c) <= c.radius) {
              hit = true;
              break;
            }
          }
          mask.at<std::uint8_t>(v, u) = hit ? 255 : 0;
          rgb.at<cv::Vec3b>(v, u) = hit ? cv::Vec3b(40, 60, 170) : plate_colour(u, v);
        }
      }
      write_image(root / cam.name / "mask" / name, mask);
      write_image(root / cam.name / "rgb" / name, rgb);
    }
  }
  write_joint_track(root / "gt" / "joints3d.csv", gt);
}

}  // namespace simcap::testing
