#include "tests/validate/synthetic_dataset.h"

#include <cstdio>

#include "core/calibration.h"
#include "core/csv.h"
#include "core/image_io.h"
#include "core/rig.h"
#include "models/humanoid.h"
#include "models/pose.h"
#include "validate/validate_job.h"
#include "validate/visibility.h"

namespace simcap::testing {
namespace fs = std::filesystem;

SyntheticDataset write_synthetic_dataset(const fs::path& root, int frames, int first_frame) {
  SyntheticDataset d;
  d.root = root;
  d.cameras = ring_rig(3, {0, 1, 0}, 4.0, 1.5, ImageSpec{160, 120, 1.0});
  write_opencv_calibration(root / "calibration" / "opencv.yaml", d.cameras);

  const Skeleton skeleton = build_humanoid();
  const auto neutral = joint_positions(skeleton, Pose::neutral(skeleton));
  d.truth.joints = he15_joints();
  d.truth.joints.push_back("skull_tip");
  for (int f = first_frame; f < first_frame + frames; ++f) {
    std::vector<Eigen::Vector3d> p;
    for (const auto& name : d.truth.joints) {
      p.push_back(neutral[skeleton.require(name)] + Eigen::Vector3d(0.05 * f, 0, 0));
    }
    d.truth.add_frame(f, p);
  }
  write_joint_track(root / "gt" / "joints3d.csv", d.truth);

  CsvWriter csv(root / "gt" / "joints2d.csv", kJoints2dColumns);
  const cv::Mat grey(120, 160, CV_8UC3, cv::Scalar(128, 128, 128));
  for (size_t f = 0; f < d.truth.frames.size(); ++f) {
    for (const Camera& cam : d.cameras) {
      for (size_t j = 0; j < d.truth.joints.size(); ++j) {
        const Eigen::Vector3d& p = d.truth.positions[f][j];
        const Eigen::Vector2d uv = cam.project(p).value();
        const std::string& joint = d.truth.joints[j];
        VisibilityLabel v = VisibilityLabel::visible;
        if (!cam.in_frustum(p)) {
          v = VisibilityLabel::out_of_frame;
        } else if (joint == "l_elbow" && cam.name == "cam01") {
          v = VisibilityLabel::self_occluded;
        } else if (joint == "r_knee" && cam.name == "cam02") {
          v = VisibilityLabel::scene_occluded;
        }
        char row[256];
        std::snprintf(row, sizeof row, "%d,%s,%s,%.4f,%.4f,%.6f,%s\n", d.truth.frames[f],
                      cam.name.c_str(), joint.c_str(), uv.x(), uv.y(), cam.to_camera(p).z(),
                      std::string(visibility_label_name(v)).c_str());
        csv.out() << row;
      }
      write_image(rgb_frame_path(root, cam.name, d.truth.frames[f]), grey);
    }
  }
  csv.commit();
  return d;
}

void write_track(
    const fs::path& track_dir, const JointTrack& truth,
    const std::function<Eigen::Vector3d(int, const std::string&, const Eigen::Vector3d&)>& f) {
  JointTrack t = truth;
  for (size_t i = 0; i < t.frames.size(); ++i) {
    for (size_t j = 0; j < t.joints.size(); ++j) {
      t.positions[i][j] = f(t.frames[i], t.joints[j], t.positions[i][j]);
    }
  }
  write_joint_track(track_dir / "joints3d.csv", t);
}

}  // namespace simcap::testing
