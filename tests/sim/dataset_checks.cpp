#include "tests/sim/dataset_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/persistence.hpp>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/image_io.h"
#include "scenes/scene.h"
#include "sim/animated_actors.h"
#include "tests/support/temp_dir.h"

namespace simcap::testing {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> actor_names(const fs::path& dir) {
  std::vector<std::string> names;
  const auto meta = nlohmann::json::parse(read_text(dir / "meta.json"));
  for (const auto& n : meta.at("actors")) {
    names.push_back(n.get<std::string>());
  }
  return names;
}

// The actor a joint column belongs to: joints of every actor after the first are named
// "<actor>/<joint>". `bare` receives the joint's own name.
int actor_of(const std::string& joint, const std::vector<std::string>& actors,
             std::string* bare = nullptr) {
  const auto slash = joint.find('/');
  if (bare) *bare = slash == std::string::npos ? joint : joint.substr(slash + 1);
  if (slash == std::string::npos) return 0;
  return static_cast<int>(std::find(actors.begin(), actors.end(), joint.substr(0, slash)) -
                          actors.begin());
}

// The joints at the times the cameras captured them, for a dataset whose meta.json has a
// "capture" section: the capture time of a 2D row follows from its v alone by the documented
// formula, and the pose at that time from the dataset's own scene.yaml.
class CapturedJoints {
 public:
  explicit CapturedJoints(const fs::path& dir) {
    const auto meta = nlohmann::json::parse(read_text(dir / "meta.json"));
    if (!meta.contains("capture")) return;
    const auto& capture = meta.at("capture");
    for (const auto& [name, ms] : capture.at("offset_ms").items()) {
      offset_s_[name] = 1e-3 * ms.get<double>();
    }
    readout_s_ = 1e-3 * capture.at("readout_ms").get<double>();
    actor_names_ = actor_names(dir);
    scene_ = std::make_unique<Scene>(load_scene(dir / "scene.yaml"));
    actors_ = std::make_unique<AnimatedActors>(*scene_);
  }
  bool timed() const { return actors_ != nullptr; }

  cv::Point3d at(const Joint2d& r, int height) const {
    double dt = offset_s_.at(r.camera);
    if (!std::isnan(r.v) && height > 1) {
      dt += readout_s_ * std::clamp(r.v, 0.0, height - 1.0) / (height - 1);
    }
    std::string joint;
    const int actor = actor_of(r.joint, actor_names_, &joint);
    const PosedActor p = actors_->posed_actor_at(actor, r.frame, dt);
    const Eigen::Vector3d x = p.joint_world.at(p.skeleton->find(joint)).translation();
    return {x.x(), x.y(), x.z()};
  }

 private:
  std::map<std::string, double> offset_s_;
  double readout_s_ = 0;
  std::vector<std::string> actor_names_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<AnimatedActors> actors_;
};

}  // namespace

std::string scene_path(const std::string& name) {
  return std::string(SIMCAP_SOURCE_DIR) + "/scenes/" + name + ".yaml";
}

int render(const std::string& scene, const fs::path& out, const std::string& extra,
           std::string* output) {
  std::string log;
  const int status =
      run_simcap("render " + scene + " -o " + out.string() + " --frames " +
                     std::to_string(kFrames) + " -q --set 'rig.resolution=[" +
                     std::to_string(kWidth) + "," + std::to_string(kHeight) + "]' " + extra,
                 &log);
  if (output) *output = log;
  EXPECT_EQ(status, 0) << log;
  return status;
}

std::map<std::string, CameraCalibration> read_calibration(const fs::path& file) {
  cv::FileStorage fs(file.string(), cv::FileStorage::READ);
  EXPECT_TRUE(fs.isOpened());
  std::map<std::string, CameraCalibration> cams;
  for (const auto& name_node : fs["camera_names"]) {
    const std::string name = name_node.string();
    const cv::FileNode n = fs[name];
    CameraCalibration c;
    n["K"] >> c.K;
    n["dist"] >> c.dist;
    n["rvec"] >> c.rvec;
    n["t"] >> c.t;
    n["R"] >> c.R;
    c.width = static_cast<int>(n["image_width"]);
    c.height = static_cast<int>(n["image_height"]);
    cams[name] = c;
  }
  return cams;
}

std::vector<Joint2d> read_joints2d(const fs::path& file) {
  CsvReader csv(file, {"frame", "camera", "joint", "u", "v", "depth", "visibility"});
  std::vector<Joint2d> rows;
  while (csv.next()) {
    rows.push_back({static_cast<int>(csv.integer(0)), csv.text(1), csv.text(2), csv.number(3),
                    csv.number(4), csv.number(5), csv.text(6)});
  }
  return rows;
}

std::map<int, std::map<std::string, cv::Point3d>> read_joints3d(const fs::path& file) {
  CsvReader csv(file, {"frame", "joint", "x", "y", "z"});
  std::map<int, std::map<std::string, cv::Point3d>> out;
  while (csv.next()) {
    out[static_cast<int>(csv.integer(0))][csv.text(1)] = {csv.number(2), csv.number(3),
                                                          csv.number(4)};
  }
  return out;
}

fs::path image_file(const fs::path& dir, const std::string& cam, const std::string& kind,
                    int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "%06d.%s", frame, kind == "depth" ? "exr" : "png");
  return dir / cam / kind / name;
}

std::map<std::string, int> count_visibility(const std::vector<Joint2d>& rows) {
  std::map<std::string, int> n;
  for (const auto& r : rows) ++n[r.visibility];
  return n;
}

void check_consistency(const fs::path& dir) {
  const std::vector<std::string> actors = actor_names(dir);
  const fs::path truth = dir / "gt" / "calibration.yaml";
  const auto cams =
      read_calibration(fs::exists(truth) ? truth : dir / "calibration" / "opencv.yaml");
  const CapturedJoints captured(dir);
  ASSERT_EQ(cams.size(), 4u);
  const auto joints3d = read_joints3d(dir / "gt" / "joints3d.csv");
  const auto rows = read_joints2d(dir / "gt" / "joints2d.csv");
  ASSERT_EQ(joints3d.size(), static_cast<size_t>(kFrames));
  ASSERT_EQ(rows.size(), kFrames * cams.size() * joints3d.begin()->second.size());

  std::map<std::pair<int, std::string>, std::pair<cv::Mat, cv::Mat>> images;  // mask, depth
  auto image_pair = [&](int frame, const std::string& cam) -> const std::pair<cv::Mat, cv::Mat>& {
    auto& p = images[{frame, cam}];
    if (p.first.empty()) {
      p = {read_image(image_file(dir, cam, "mask", frame)),
           read_image(image_file(dir, cam, "depth", frame))};
    }
    return p;
  };
  for (const Joint2d& r : rows) {
    SCOPED_TRACE("frame " + std::to_string(r.frame) + " " + r.camera + " " + r.joint);
    const CameraCalibration& c = cams.at(r.camera);
    const cv::Point3d X =
        captured.timed() ? captured.at(r, c.height) : joints3d.at(r.frame).at(r.joint);
    cv::Mat Xc = c.R * cv::Mat(X) + c.t;
    EXPECT_NEAR(r.depth, Xc.at<double>(2), 1e-6);
    if (std::isnan(r.u)) {
      EXPECT_LE(r.depth, 0);
      EXPECT_EQ(r.visibility, "out_of_frame");
      continue;
    }
    std::vector<cv::Point2d> px;
    cv::projectPoints(std::vector<cv::Point3d>{X}, c.rvec, c.t, c.K, c.dist, px);
    EXPECT_LT(std::hypot(px[0].x - r.u, px[0].y - r.v), 1e-3);

    const bool inside =
        r.depth > 0 && r.u >= -0.5 && r.u < c.width - 0.5 && r.v >= -0.5 && r.v < c.height - 0.5;
    if (!inside) {
      EXPECT_EQ(r.visibility, "out_of_frame");
      continue;
    }
    const auto& [mask, depth] = image_pair(r.frame, r.camera);
    const int x = static_cast<int>(std::lround(r.u)), y = static_cast<int>(std::lround(r.v));
    const int m = mask.at<std::uint8_t>(y, x);
    const double d = depth.at<float>(y, x);
    // Tables hold 7 decimals and the image float32: 1e-5 m covers both roundings.
    // The mask value of the joint's own actor: 255 with one actor, else 1 + its index.
    const int own = actors.size() == 1 ? 255 : 1 + actor_of(r.joint, actors);
    if (r.visibility == "visible") {
      EXPECT_EQ(m, own);
      EXPECT_LE(std::abs(d - r.depth), 0.15 + 1e-5);
    } else if (r.visibility == "self_occluded") {
      EXPECT_EQ(m, own);
      EXPECT_LT(d, r.depth - 0.15 + 1e-5);
    } else if (r.visibility == "scene_occluded") {
      EXPECT_NE(m, own);
      // Another actor hides a joint from anywhere in front of it; the room and occluders from
      // beyond the tolerance.
      const bool other_actor = m != 0 && actors.size() > 1;
      EXPECT_LT(d, r.depth - (other_actor ? 0.0 : 0.15) + 1e-5);
    } else {
      ADD_FAILURE() << "joint inside the image marked " << r.visibility;
    }
  }

  // The mask is exactly where a body part is seen.
  for (const auto& [name, c] : cams) {
    for (int f = 0; f < kFrames; ++f) {
      const cv::Mat mask = read_image(image_file(dir, name, "mask", f));
      const cv::Mat parts = read_image(image_file(dir, name, "parts", f));
      EXPECT_EQ(cv::countNonZero((mask != 0) != (parts != 0)), 0) << name << " frame " << f;
    }
  }
}

}  // namespace simcap::testing
