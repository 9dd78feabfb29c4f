// The keypoint sets `simcap render` writes next to its own tables: gt/keypoints_coco.json
// checked against gt/joints2d.csv, the mask images (OpenCV's bounding box and pixel count) and
// the image files, and gt/joints3d_h36m17.csv against gt/joints3d.csv.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/image_io.h"
#include "tests/support/occluders_dataset.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using Json = nlohmann::json;
using testing::run_simcap;
using testing::TempDir;

constexpr int kFrames = testing::kOccludersFrames;

class KeypointDataset : public ::testing::Test {
 protected:
  static fs::path dataset() { return testing::occluders_dataset(); }
};

struct Row2d {
  double u, v;
  std::string visibility;
};

// gt/joints2d.csv by (frame, camera, joint).
std::map<std::tuple<int, std::string, std::string>, Row2d> read_joints2d(const fs::path& file) {
  std::map<std::tuple<int, std::string, std::string>, Row2d> rows;
  CsvReader csv(file, {"frame", "camera", "joint", "u", "v", "depth", "visibility"});
  while (csv.next()) {
    rows[{static_cast<int>(csv.integer(0)), csv.text(1), csv.text(2)}] = {
        csv.number(3), csv.number(4), csv.text(6)};
  }
  return rows;
}

// joints3d-style tables by (frame, joint).
std::map<std::pair<int, std::string>, Eigen::Vector3d> read_joints3d(const fs::path& file) {
  std::map<std::pair<int, std::string>, Eigen::Vector3d> rows;
  CsvReader csv(file, {"frame", "joint", "x", "y", "z"});
  while (csv.next()) {
    rows[{static_cast<int>(csv.integer(0)), csv.text(1)}] = {csv.number(2), csv.number(3),
                                                             csv.number(4)};
  }
  return rows;
}

TEST_F(KeypointDataset, CocoAnnotationsAgreeWithTablesAndMasks) {
  const Json coco = Json::parse(read_text(dataset() / "gt" / "keypoints_coco.json"));
  const auto joints2d = read_joints2d(dataset() / "gt" / "joints2d.csv");
  ASSERT_EQ(coco["categories"].size(), 1u);
  const Json& person = coco["categories"][0];
  EXPECT_EQ(person["name"], "person");
  ASSERT_EQ(person["keypoints"].size(), 17u);
  EXPECT_EQ(person["skeleton"].size(), 19u);
  // COCO's limb and joint names, mapped to the H-Anim joints whose 2D rows they must equal.
  const std::map<std::string, std::string> hanim = {
      {"left_shoulder", "l_shoulder"}, {"right_shoulder", "r_shoulder"},
      {"left_elbow", "l_elbow"},       {"right_elbow", "r_elbow"},
      {"left_wrist", "l_radiocarpal"}, {"right_wrist", "r_radiocarpal"},
      {"left_hip", "l_hip"},           {"right_hip", "r_hip"},
      {"left_knee", "l_knee"},         {"right_knee", "r_knee"},
      {"left_ankle", "l_talocrural"},  {"right_ankle", "r_talocrural"}};

  ASSERT_EQ(coco["images"].size(), 4u * kFrames);
  std::map<long, Json> images;
  for (const Json& im : coco["images"]) {
    EXPECT_TRUE(fs::is_regular_file(dataset() / im["file_name"].get<std::string>()));
    EXPECT_EQ(im["width"], 320);
    EXPECT_EQ(im["height"], 240);
    images[im["id"]] = im;
  }
  std::map<int, int> flags;
  for (const Json& ann : coco["annotations"]) {
    const Json& im = images.at(ann["image_id"]);
    const int frame = im["frame"];
    const std::string camera = im["camera"];
    SCOPED_TRACE(camera + " frame " + std::to_string(frame));
    // bbox and area from the mask image, by OpenCV.
    const cv::Mat mask = read_image(
        dataset() / im["file_name"].get<std::string>().replace(camera.size() + 1, 3, "mask"));
    const cv::Rect box = cv::boundingRect(mask);
    EXPECT_EQ(ann["bbox"], Json::array({box.x, box.y, box.width, box.height}));
    EXPECT_EQ(ann["area"], cv::countNonZero(mask));
    int labelled = 0;
    for (int k = 0; k < 17; ++k) {
      const std::string name = person["keypoints"][k];
      const double x = ann["keypoints"][3 * k], y = ann["keypoints"][3 * k + 1];
      const int v = ann["keypoints"][3 * k + 2];
      ++flags[v];
      labelled += v > 0;
      if (v == 0) {
        EXPECT_EQ(x, 0.0);
        EXPECT_EQ(y, 0.0);
      }
      const auto it = hanim.find(name);
      if (it == hanim.end()) continue;
      const Row2d& row = joints2d.at({frame, camera, it->second});
      const int expected = row.visibility == "visible"        ? 2
                           : row.visibility == "out_of_frame" ? 0
                                                              : 1;
      EXPECT_EQ(v, expected) << name;
      EXPECT_EQ(ann["visibility"][k], row.visibility) << name;
      if (v > 0) {
        EXPECT_NEAR(x, row.u, 0.0005 + 1e-6) << name;
        EXPECT_NEAR(y, row.v, 0.0005 + 1e-6) << name;
      }
    }
    EXPECT_EQ(ann["num_keypoints"], labelled);
  }
  EXPECT_EQ(coco["annotations"].size(), 4u * kFrames);  // the actor is in every view
  EXPECT_GT(flags[2], 0);
  EXPECT_GT(flags[1], 0);  // hidden by an occluder or the body
}

TEST_F(KeypointDataset, Human36mJointsAreTheMatchingHAnimJoints) {
  const auto h36m = read_joints3d(dataset() / "gt" / "joints3d_h36m17.csv");
  const auto hanim = read_joints3d(dataset() / "gt" / "joints3d.csv");
  ASSERT_EQ(h36m.size(), 17u * kFrames);
  const std::map<std::string, std::string> same = {
      {"RHip", "r_hip"},     {"RKnee", "r_knee"},         {"RFoot", "r_talocrural"},
      {"LHip", "l_hip"},     {"LKnee", "l_knee"},         {"LFoot", "l_talocrural"},
      {"Spine", "vt10"},     {"Thorax", "vc7"},           {"LShoulder", "l_shoulder"},
      {"LElbow", "l_elbow"}, {"LWrist", "l_radiocarpal"}, {"RShoulder", "r_shoulder"},
      {"RElbow", "r_elbow"}, {"RWrist", "r_radiocarpal"}};
  for (int f = 0; f < kFrames; ++f) {
    for (const auto& [h, a] : same) {
      EXPECT_LT((h36m.at({f, h}) - hanim.at({f, a})).norm(), 1e-9) << h;
    }
    const Eigen::Vector3d mid = 0.5 * (hanim.at({f, "l_hip"}) + hanim.at({f, "r_hip"}));
    EXPECT_LT((h36m.at({f, "Hip"}) - mid).norm(), 2e-7);  // the tables round to 0.1 um
    // The head's top and the nose keep their distances from the skull base, which carries them.
    for (const char* point : {"Head", "Neck/Nose"}) {
      const auto distance = [&](int frame) {
        return (h36m.at({frame, point}) - hanim.at({frame, "skullbase"})).norm();
      };
      EXPECT_GT(distance(f), 0.05) << point;
      EXPECT_NEAR(distance(f), distance(0), 1e-6) << point;
    }
  }
}

}  // namespace
}  // namespace simcap
