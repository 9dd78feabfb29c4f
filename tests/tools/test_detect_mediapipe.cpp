// scripts/detect_mediapipe end to end: MediaPipe Pose in chromium on a small rendered dataset,
// checked against the dataset's own COCO keypoints; its set-up missing is a failure, not a skip.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::run_shell;
using testing::run_simcap;
using testing::shell_words;
using testing::TempDir;

const fs::path kSource = SIMCAP_SOURCE_DIR;

int run_detector(const std::vector<std::string>& args, std::string* output) {
  return run_shell(
      (kSource / "scripts" / "detect_mediapipe").string() + shell_words(args) + " 2>&1", output);
}

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// BlazePose-33 index of each COCO-17 limb keypoint (shoulders .. ankles, COCO 5..16).
const std::map<int, int> kCocoToBlazePose = {{5, 11},  {6, 12},  {7, 13},  {8, 14},
                                             {9, 15},  {10, 16}, {11, 23}, {12, 24},
                                             {13, 25}, {14, 26}, {15, 27}, {16, 28}};

TEST(DetectMediapipe, SetUpIsInstalled) {
  const fs::path modules = kSource / "tools" / "mediapipe" / "node_modules";
  EXPECT_TRUE(fs::exists(modules / "puppeteer-core") && fs::exists(modules / "@mediapipe" / "pose"))
      << modules << " is missing: run `make setup-mediapipe` (make test runs it)";
  EXPECT_TRUE(fs::exists("/usr/bin/chromium"))
      << "Debian's chromium is missing: run `make setup-mediapipe` (make test runs it)";
}

TEST(DetectMediapipe, BadInputsAreClearErrorsWithNoOutput) {
  TempDir dir;
  std::string out;
  const std::string det = (dir / "det.json").string();
  EXPECT_EQ(run_detector({(dir / "nowhere").string(), "-o", det}, &out), 1) << out;
  EXPECT_NE(out.find("nowhere: no such dataset folder"), std::string::npos) << out;
  EXPECT_EQ(run_detector({dir.path().string(), "-o", det}, &out), 1) << out;
  EXPECT_NE(out.find("meta.json: not found"), std::string::npos) << out;
  EXPECT_EQ(run_detector({dir.path().string(), "-o", det, "--every", "0"}, &out), 2) << out;
  EXPECT_NE(out.find("--every: expected a whole number >= 1"), std::string::npos) << out;
  EXPECT_EQ(run_detector({dir.path().string()}, &out), 2) << out;
  EXPECT_NE(out.find("-o DET.json is required"), std::string::npos) << out;

  ASSERT_EQ(run_simcap("render " + (kSource / "scenes" / "studio4.yaml").string() + " -o " +
                           (dir / "ds").string() + " --frames 1 --cameras cam00 -q",
                       &out),
            0)
      << out;
  EXPECT_EQ(run_detector({(dir / "ds").string(), "-o", det, "--cameras", "cam07"}, &out), 1);
  EXPECT_NE(out.find("'cam07' is not a camera"), std::string::npos) << out;
  fs::remove(dir / "ds" / "cam00" / "rgb" / "000000.png");
  EXPECT_EQ(run_detector({(dir / "ds").string(), "-o", det}, &out), 1);
  EXPECT_NE(out.find("cam00/rgb/000000.png: not found"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(det));
}

TEST(DetectMediapipe, FindsThePersonInEveryImageWhereTheTruthIs) {
  TempDir dir;
  std::string out;
  const fs::path ds = dir / "ds";
  ASSERT_EQ(run_simcap("render " + (kSource / "scenes" / "studio4.yaml").string() + " -o " +
                           ds.string() + " --frames 2 --cameras cam00,cam02 -q",
                       &out),
            0)
      << out;
  const fs::path det = dir / "out" / "det.json";
  ASSERT_EQ(run_detector({ds.string(), "-o", det.string(), "--mode", "images", "--quiet"}, &out), 0)
      << out;
  EXPECT_EQ(out, "");  // --quiet
  for (const auto& entry : fs::directory_iterator(dir / "out"))
    EXPECT_EQ(entry.path().filename(), "det.json") << "left behind: " << entry.path();

  const nlohmann::json results = read_json(det);
  const nlohmann::json truth = read_json(ds / "gt" / "keypoints_coco.json");
  std::map<int, nlohmann::json> truth_of_image;
  for (const auto& a : truth["annotations"]) truth_of_image[a["image_id"].get<int>()] = a;
  std::map<int, std::string> file_of_image;
  for (const auto& im : truth["images"])
    file_of_image[im["id"].get<int>()] = im["file_name"].get<std::string>();

  ASSERT_TRUE(results.is_array());
  ASSERT_EQ(results.size(), 4u) << "one result per image, the person found in each";
  std::set<int> ids;
  std::vector<double> errors;
  for (const auto& r : results) {
    const int id = r.at("image_id").get<int>();
    ids.insert(id);
    EXPECT_EQ(r.at("file_name").get<std::string>(), file_of_image.at(id));
    EXPECT_EQ(r.at("category_id").get<int>(), 1);
    const auto& k = r.at("keypoints");
    ASSERT_EQ(k.size(), 99u);
    EXPECT_GT(r.at("score").get<double>(), 0.5);
    EXPECT_LE(r.at("score").get<double>(), 1.0);
    const auto& t = truth_of_image.at(id)["keypoints"];
    for (const auto& [coco, blaze] : kCocoToBlazePose) {
      EXPECT_GE(k[3 * blaze + 2].get<double>(), 0.0);
      EXPECT_LE(k[3 * blaze + 2].get<double>(), 1.0);
      errors.push_back(std::hypot(k[3 * blaze].get<double>() - t[3 * coco].get<double>(),
                                  k[3 * blaze + 1].get<double>() - t[3 * coco + 1].get<double>()));
    }
  }
  // The dataset's cameras are cam00 and cam02, frames 0 and 1: image_id = 1 + frame * 2 + camera.
  EXPECT_EQ(ids, (std::set<int>{1, 2, 3, 4}));
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  // MediaPipe's limb keypoints lie a few pixels from the joint centres; a wrong image, camera
  // or coordinate convention (normalised, flipped, other camera) puts them tens of pixels off.
  EXPECT_LT(errors[errors.size() / 2], 10.0);

  // Every image is detected on its own: one image alone (cam02 frame 0, image 2) gives the same
  // bytes as in the run.
  const fs::path one = dir / "one.json";
  ASSERT_EQ(run_detector({ds.string(), "-o", one.string(), "--mode", "images", "--cameras", "cam02",
                          "--every", "2", "-q"},
                         &out),
            0)
      << out;
  const nlohmann::json alone = read_json(one);
  ASSERT_EQ(alone.size(), 1u);
  EXPECT_EQ(alone[0].dump(), results[1].dump());
}

TEST(DetectMediapipe, ClosedLoopTriangulatesItsKeypoints) {
  TempDir dir;
  std::string out;
  ASSERT_EQ(
      run_simcap("loop " + (kSource / "scenes" / "studio4.yaml").string() + " -o " +
                     (dir / "loop").string() + " --frames 2 --no-media --detector mediapipe -q",
                 &out),
      0)
      << out;
  EXPECT_NE(out.find("mediapipe"), std::string::npos) << out;
  EXPECT_EQ(read_json(dir / "loop" / "detections.json").size(), 8u);  // 2 frames x 4 cameras
  const nlohmann::json metrics = read_json(dir / "loop" / "report" / "metrics.json");
  EXPECT_EQ(metrics["frame_count"], 2);
  // 29.6 mm over 60 frames (tools/mediapipe/README.md); a wrong camera order or pixel
  // convention triangulates nothing or lands decimetres off.
  EXPECT_LT(metrics["mpjpe_mm"].get<double>(), 60.0);
}

}  // namespace
}  // namespace simcap
