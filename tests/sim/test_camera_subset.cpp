// `simcap render --cameras`: a dataset of some of a rig's cameras holds those cameras in every
// file, with the names, calibration and images (noise included) they have in the full rig, and
// the tracker and the validator read it as they read any dataset.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/calibration.h"
#include "core/csv.h"
#include "scenes/scene.h"
#include "tests/support/file_tree.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using testing::read_tree;
using testing::run_simcap;
using testing::TempDir;

using Names = std::set<std::string>;

std::string studio4() {
  return std::string(SIMCAP_SOURCE_DIR) + "/scenes/studio4.yaml";
}

// Two small frames with the seeded parts (anti-aliasing jitter, sensor noise) switched on.
std::string render_args(const fs::path& out) {
  return "render " + studio4() + " -o " + out.string() +
         " -q --frames 2 --set 'rig.resolution=[160,120]' --set render.samples_per_pixel=2"
         " --set noise.rgb_sigma=2 --set noise.depth_sigma=0.002";
}

template <typename Cameras>
Names names_of(const Cameras& cams) {
  Names names;
  for (const Camera& c : cams) names.insert(c.name);
  return names;
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class CameraSubset : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    std::string log;
    ASSERT_EQ(run_simcap(render_args(full()), &log), 0) << log;
    // Out of rig order on purpose: the dataset keeps the rig's order.
    ASSERT_EQ(run_simcap(render_args(subset()) + " --cameras cam02,cam00", &log), 0) << log;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path full() { return dir_->path() / "full"; }
  static fs::path subset() { return dir_->path() / "subset"; }
  static TempDir* dir_;
};
TempDir* CameraSubset::dir_ = nullptr;

TEST_F(CameraSubset, EveryFileHoldsExactlyTheChosenCameras) {
  const fs::path d = subset();
  const Names chosen = {"cam00", "cam02"};
  const auto meta = nlohmann::json::parse(read_text(d / "meta.json"));
  EXPECT_EQ(meta.at("cameras"), nlohmann::json({"cam00", "cam02"}));
  EXPECT_EQ(names_of(read_opencv_calibration(d / "calibration" / "opencv.yaml")), chosen);
  EXPECT_EQ(names_of(read_easymocap_calibration(d / "calibration" / "intri.yml",
                                                d / "calibration" / "extri.yml")),
            chosen);
  EXPECT_EQ(names_of(load_scene(d / "scene.yaml").cameras), chosen);
  Names plates, folders;
  for (const auto& e : fs::directory_iterator(d / "background")) {
    plates.insert(e.path().stem().string());
  }
  for (const auto& e : fs::directory_iterator(d)) {
    if (e.is_directory() && e.path().filename().string().rfind("cam", 0) == 0) {
      folders.insert(e.path().filename().string());
    }
  }
  EXPECT_EQ(plates, chosen);
  EXPECT_EQ(folders, chosen);
  CsvReader csv(d / "gt" / "joints2d.csv",
                {"frame", "camera", "joint", "u", "v", "depth", "visibility"});
  std::map<std::string, int> rows;
  while (csv.next()) ++rows[csv.text(1)];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_GT(rows["cam00"], 0);
  EXPECT_EQ(rows["cam00"], rows["cam02"]);
}

TEST_F(CameraSubset, CamerasKeepTheirCalibrationImagesAndTruth) {
  const auto full_cams = read_opencv_calibration(full() / "calibration" / "opencv.yaml");
  for (const Camera& c : read_opencv_calibration(subset() / "calibration" / "opencv.yaml")) {
    const Camera& f = find_camera(full_cams, c.name, full());
    EXPECT_EQ(c.K, f.K) << c.name;
    EXPECT_EQ(c.R, f.R) << c.name;
    EXPECT_EQ(c.t, f.t) << c.name;
  }
  const auto a = read_tree(full()), b = read_tree(subset());
  int images = 0;
  for (const auto& [name, content] : b) {
    if (name.rfind("cam", 0) != 0 && name.rfind("background/", 0) != 0) continue;
    EXPECT_TRUE(a.count(name) && a.at(name) == content) << name << " differs from the full rig";
    ++images;
  }
  EXPECT_EQ(images, 2 + 2 * 2 * 4);  // plates, then 2 cameras x 2 frames x 4 kinds
  std::vector<std::string> expected;
  for (const auto& line : lines(a.at("gt/joints2d.csv"))) {
    if (line.find(",cam01,") == std::string::npos && line.find(",cam03,") == std::string::npos) {
      expected.push_back(line);
    }
  }
  EXPECT_EQ(lines(b.at("gt/joints2d.csv")), expected);
  EXPECT_EQ(a.at("gt/joints3d.csv"), b.at("gt/joints3d.csv"));
}

TEST_F(CameraSubset, TrackAndValidateRunOnIt) {
  TempDir dir;
  std::string log;
  ASSERT_EQ(
      run_simcap("track " + subset().string() + " -o " + (dir / "track").string() + " -q", &log), 0)
      << log;
  ASSERT_EQ(run_simcap("validate " + subset().string() + " " + (dir / "track").string() + " -o " +
                           (dir / "report").string() + " -q",
                       &log),
            0)
      << log;
  const auto metrics = nlohmann::json::parse(read_text(dir / "report" / "metrics.json"));
  EXPECT_EQ(metrics.at("frame_count").get<int>(), 2);
  EXPECT_EQ(metrics.at("visibility").at("camera_count").get<int>(), 2);
}

TEST_F(CameraSubset, UnknownOrRepeatedNamesFailAndWriteNothing) {
  TempDir dir;
  std::string log;
  EXPECT_EQ(run_simcap(render_args(dir / "out") + " --cameras cam00,cam07", &log), 1);
  EXPECT_NE(log.find("'cam07'"), std::string::npos) << log;
  EXPECT_NE(log.find("cam00, cam01, cam02, cam03"), std::string::npos) << log;
  EXPECT_EQ(run_simcap(render_args(dir / "out") + " --cameras cam01,cam01", &log), 1);
  EXPECT_NE(log.find("cam01 is listed twice"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST_F(CameraSubset, ResumeNeedsTheSameCameras) {
  TempDir dir;
  const fs::path d = dir / "d";
  fs::copy(subset(), d, fs::copy_options::recursive);
  const auto before = read_tree(d);
  std::string log;
  for (const std::string cameras : {"", " --cameras cam01", " --cameras cam00,cam02,cam03"}) {
    SCOPED_TRACE(cameras);
    EXPECT_EQ(run_simcap(render_args(d) + " --resume" + cameras, &log), 1);
    EXPECT_NE(log.find("has the cameras cam00, cam02,"), std::string::npos) << log;
    EXPECT_EQ(read_tree(d), before);
  }
  EXPECT_NE(log.find("this render has cam00, cam02, cam03"), std::string::npos) << log;
  ASSERT_EQ(run_simcap(render_args(d) + " --resume --cameras cam00,cam02", &log), 0) << log;
  const auto meta = nlohmann::json::parse(read_text(d / "meta.json"));
  EXPECT_EQ(meta.at("timings").at("frames_resumed").get<int>(), 2);
}

}  // namespace
}  // namespace simcap
