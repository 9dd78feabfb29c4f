// `simcap render` end to end: the dataset's files agree with each other exactly — 2D joints
// with OpenCV's projection of the 3D joints through the stored calibration, visibility with
// the mask and depth images, masks with part labels — and renders are deterministic, resumable
// and refuse bad input without leaving files behind.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/core/persistence.hpp>
#include <set>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/image_io.h"
#include "scenes/scene.h"
#include "sim/animated_actors.h"
#include "tests/sim/dataset_checks.h"
#include "tests/support/file_tree.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using namespace simcap::testing;

class StudioDataset : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir;
    render(scene_path("studio4"), dir_->path() / "d");
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path dataset() { return dir_->path() / "d"; }
  static TempDir* dir_;
};
TempDir* StudioDataset::dir_ = nullptr;

TEST_F(StudioDataset, HasEveryFileOfTheLayout) {
  const fs::path d = dataset();
  for (const char* f :
       {"scene.yaml", "meta.json", "parts.json", "calibration/opencv.yaml", "calibration/intri.yml",
        "calibration/extri.yml", "calibration/calibration.toml", "calibration/colmap/cameras.txt",
        "calibration/colmap/images.txt", "calibration/colmap/points3D.txt",
        "calibration/blender_cameras.py", "gt/joints3d.csv", "gt/joints2d.csv", "gt/angles.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(d / f)) << f;
  }
  for (const char* cam : {"cam00", "cam01", "cam02", "cam03"}) {
    const cv::Mat plate = read_image(d / "background" / (std::string(cam) + ".png"));
    EXPECT_EQ(plate.type(), CV_8UC3);
    for (int f = 0; f < kFrames; ++f) {
      for (const char* kind : kKinds) EXPECT_TRUE(fs::exists(image_file(d, cam, kind, f)));
    }
    EXPECT_FALSE(fs::exists(image_file(d, cam, "rgb", kFrames)));
  }
  EXPECT_EQ(read_image(image_file(d, "cam00", "rgb", 0)).type(), CV_8UC3);
  EXPECT_EQ(read_image(image_file(d, "cam00", "depth", 0)).type(), CV_32FC1);
  EXPECT_EQ(read_image(image_file(d, "cam00", "mask", 0)).type(), CV_8UC1);
  EXPECT_EQ(read_image(image_file(d, "cam00", "parts", 0)).size(), cv::Size(kWidth, kHeight));
  const auto meta = nlohmann::json::parse(read_text(d / "meta.json"));
  EXPECT_TRUE(meta.at("complete").get<bool>());
  EXPECT_EQ(meta.at("frame_count").get<int>(), kFrames);
  EXPECT_EQ(meta.at("conventions").at("visibility_tolerance_m").get<double>(), 0.15);
}

TEST_F(StudioDataset, TablesImagesAndCalibrationAgree) {
  check_consistency(dataset());
  auto n = count_visibility(read_joints2d(dataset() / "gt" / "joints2d.csv"));
  // Both outcomes occur, so the agreement above was tested on each.
  EXPECT_GT(n["visible"], 100);
  EXPECT_GT(n["self_occluded"], 5);
}

TEST_F(StudioDataset, PartLabelsAreTheLegend) {
  const auto legend = nlohmann::json::parse(read_text(dataset() / "parts.json"));
  std::set<int> labels;
  for (const auto& p : legend.at("parts")) labels.insert(p.at("label").get<int>());
  EXPECT_TRUE(labels.count(1));  // sacrum, of humanoid_root
  std::set<int> seen;
  for (const char* cam : {"cam00", "cam01", "cam02", "cam03"}) {
    const cv::Mat parts = read_image(image_file(dataset(), cam, "parts", 0));
    for (int y = 0; y < parts.rows; ++y) {
      for (int x = 0; x < parts.cols; ++x) seen.insert(parts.at<std::uint8_t>(y, x));
    }
  }
  seen.erase(0);
  EXPECT_GT(seen.size(), 10u);
  for (const int label : seen) EXPECT_TRUE(labels.count(label)) << label;
}

TEST_F(StudioDataset, AnglesAreUnitQuaternionsForEveryJointAndFrame) {
  CsvReader csv(dataset() / "gt" / "angles.csv", {"frame", "joint", "qw", "qx", "qy", "qz"});
  int rows = 0;
  while (csv.next()) {
    const double w = csv.number(2), x = csv.number(3), y = csv.number(4), z = csv.number(5);
    EXPECT_NEAR(w * w + x * x + y * y + z * z, 1.0, 1e-7);
    EXPECT_GE(w, 0);
    ++rows;
  }
  EXPECT_EQ(rows,
            kFrames * static_cast<int>(
                          read_joints3d(dataset() / "gt" / "joints3d.csv").begin()->second.size()));
}

TEST(RenderDataset, OccludersHideJointsAndTheTablesSaySo) {
  TempDir dir;
  ASSERT_EQ(render(scene_path("occluders"), dir / "d"), 0);
  check_consistency(dir / "d");
  // The pillars stand between two cameras and the start of the walk.
  EXPECT_GT(count_visibility(read_joints2d(dir / "d" / "gt" / "joints2d.csv"))["scene_occluded"],
            20);
}

TEST(RenderDataset, ActorsSharingABodyAreInstancedAndLabelledApart) {
  TempDir dir;
  // Two actors walking the same clip side by side: one skinned mesh, two instances.
  std::ofstream(dir / "pair.yaml") << R"(room: {size: [5, 3, 5]}
lights: [{type: directional, direction: [-0.3, -1.0, -0.4], intensity: 0.8}]
rig: {type: corners, height: 2.5, inset: 0.1, target: [0, 1, 0], resolution: [640, 480],
      hfov_deg: 75}
actors:
  - name: actor0
    motion: {bvh: "asset:cmu_131_01_start_walk_stop.bvh", units: 0.05644444444444444}
    offset: [-0.6, 0, 0.6]
  - name: actor1
    motion: {bvh: "asset:cmu_131_01_start_walk_stop.bvh", units: 0.05644444444444444}
    offset: [0.4, 0, 0.6]
    colors: {shirt: [0.7, 0.2, 0.2]}
)";
  EXPECT_EQ(AnimatedActors(load_scene(dir / "pair.yaml")).body_count(), 1);
  ASSERT_EQ(render((dir / "pair.yaml").string(), dir / "d"), 0);
  check_consistency(dir / "d");
  // The second actor's joints are the first's, moved by the difference of the offsets.
  const auto joints = read_joints3d(dir / "d" / "gt" / "joints3d.csv");
  for (const auto& [frame, by_name] : joints) {
    const cv::Point3d a = by_name.at("l_knee"), b = by_name.at("actor1/l_knee");
    EXPECT_NEAR(b.x - a.x, 1.0, 1e-6);
    EXPECT_NEAR(b.y - a.y, 0.0, 1e-6);
    EXPECT_NEAR(b.z - a.z, 0.0, 1e-6);
  }
  std::set<int> values;
  for (const char* cam : {"cam00", "cam01", "cam02", "cam03"}) {
    const cv::Mat mask = read_image(image_file(dir / "d", cam, "mask", 1));
    for (int y = 0; y < mask.rows; ++y) {
      for (int x = 0; x < mask.cols; ++x) values.insert(mask.at<std::uint8_t>(y, x));
    }
  }
  EXPECT_EQ(values, (std::set<int>{0, 1, 2}));
}

TEST(RenderDataset, TwoPeopleCrossingHideEachOtherAndTheTablesSaySo) {
  TempDir dir;
  // Frames 50-53 of scenes/two_people.yaml: actor1 walks between cam00 and actor0.
  ASSERT_EQ(render(scene_path("two_people"), dir / "d", "--set render.first_frame=170"), 0);
  check_consistency(dir / "d");
  // Every joint of actor0 whose pixel shows actor1 in front of it (more than the visibility
  // tolerance nearer, by the depth map) is labelled scene_occluded, and there are such joints.
  int hidden = 0;
  for (const Joint2d& r : read_joints2d(dir / "d" / "gt" / "joints2d.csv")) {
    if (r.joint.find('/') != std::string::npos || r.visibility == "out_of_frame") continue;
    const int u = static_cast<int>(std::lround(r.u)), v = static_cast<int>(std::lround(r.v));
    const cv::Mat mask = read_image(image_file(dir / "d", r.camera, "mask", r.frame));
    if (mask.at<std::uint8_t>(v, u) != 2) continue;
    const cv::Mat depth = read_image(image_file(dir / "d", r.camera, "depth", r.frame));
    if (depth.at<float>(v, u) >= r.depth - 0.15) continue;
    EXPECT_EQ(r.visibility, "scene_occluded") << r.camera << " " << r.frame << " " << r.joint;
    ++hidden;
  }
  EXPECT_GT(hidden, 10);
}

TEST(RenderDataset, NormalsAreUnitVectorsFacingTheCamera) {
  TempDir dir;
  ASSERT_EQ(render(scene_path("studio4"), dir / "d", "--set render.normals=true"), 0);
  const auto cams = read_calibration(dir / "d" / "calibration" / "opencv.yaml");
  const CameraCalibration& c = cams.at("cam02");
  const cv::Mat normal = read_image(dir / "d" / "cam02" / "normal" / "000001.exr");
  const cv::Mat mask = read_image(image_file(dir / "d", "cam02", "mask", 1));
  ASSERT_EQ(normal.type(), CV_32FC3);
  int pixels = 0, body = 0, facing_away = 0;
  for (int y = 0; y < normal.rows; y += 3) {
    for (int x = 0; x < normal.cols; x += 3) {
      const cv::Vec3f n = normal.at<cv::Vec3f>(y, x);
      EXPECT_NEAR(cv::norm(n), 1.0, 1e-5);
      // The ray through the pixel, in world coordinates: R^T K^-1 (x, y, 1) is close enough to
      // tell which way the surface faces.
      cv::Mat ray = c.R.t() * c.K.inv() * (cv::Mat_<double>(3, 1) << x, y, 1);
      ++pixels;
      facing_away += ray.dot(cv::Mat(cv::Vec3d(n[0], n[1], n[2]))) >= 0;
      body += mask.at<std::uint8_t>(y, x) != 0;
    }
  }
  EXPECT_GT(body, 20);
  // Smoothly interpolated normals may tip past 90 degrees only at the body's silhouette.
  EXPECT_LT(facing_away, body / 10 + 1);
  EXPECT_LT(facing_away, pixels / 1000);
}

TEST(RenderDataset, SameSeedGivesByteIdenticalFiles) {
  TempDir dir;
  // Anti-aliasing jitter and sensor noise are the seeded parts.
  const std::string noisy =
      "--set render.samples_per_pixel=3 --set noise.rgb_sigma=2 --set noise.depth_sigma=0.002";
  ASSERT_EQ(render(scene_path("studio4"), dir / "a", noisy + " --seed 7"), 0);
  ASSERT_EQ(render(scene_path("studio4"), dir / "b", noisy + " --seed 7"), 0);
  ASSERT_EQ(render(scene_path("studio4"), dir / "c", noisy + " --seed 8"), 0);
  auto a = read_tree(dir / "a"), b = read_tree(dir / "b"), c = read_tree(dir / "c");
  ASSERT_EQ(a.size(), b.size());
  for (auto* tree : {&a, &b}) {
    auto meta = nlohmann::json::parse((*tree)["meta.json"]);
    meta.erase("timings");  // wall-clock times are the one thing that may differ
    (*tree)["meta.json"] = meta.dump();
  }
  for (const auto& [name, content] : a) {
    EXPECT_TRUE(b.count(name) && b[name] == content) << name << " differs";
  }
  EXPECT_NE(a["cam00/rgb/000001.png"], c["cam00/rgb/000001.png"]);
  EXPECT_NE(a["cam00/depth/000001.exr"], c["cam00/depth/000001.exr"]);
  EXPECT_EQ(a["gt/joints2d.csv"], c["gt/joints2d.csv"]);
}

TEST(RenderDataset, ResumeRendersOnlyIncompleteFrames) {
  TempDir dir;
  const fs::path d = dir / "d";
  ASSERT_EQ(render(scene_path("studio4"), d), 0);
  const auto fresh = read_tree(d);
  // Frame 0 stays complete but is marked, so re-rendering it would show; frame 2 loses a file
  // as if the render had been stopped while writing it; the tables are gone.
  write_text_atomic(image_file(d, "cam01", "rgb", 0), "marker");
  fs::remove(image_file(d, "cam02", "parts", 2));
  fs::remove(d / "gt" / "joints2d.csv");
  std::ofstream(d / "cam02" / "parts" / ".000002.tmp123_0.png") << "half a file";
  ASSERT_EQ(render(scene_path("studio4"), d, "--resume"), 0);
  const auto resumed = read_tree(d);
  EXPECT_EQ(resumed.at("cam01/rgb/000000.png"), "marker");
  EXPECT_EQ(resumed.count("cam02/parts/.000002.tmp123_0.png"), 0u);
  for (const auto& [name, content] : fresh) {
    if (name == "meta.json" || name == "cam01/rgb/000000.png") continue;
    EXPECT_TRUE(resumed.count(name) && resumed.at(name) == content) << name;
  }
  const auto meta = nlohmann::json::parse(resumed.at("meta.json"));
  EXPECT_EQ(meta.at("timings").at("frames_rendered").get<int>(), 1);
  EXPECT_EQ(meta.at("timings").at("frames_resumed").get<int>(), kFrames - 1);

  // A different scene is not resumed into the same folder.
  std::string log;
  EXPECT_NE(run_simcap("render " + scene_path("occluders") + " -o " + d.string() +
                           " --frames 4 -q --resume --set 'rig.resolution=[320,240]'",
                       &log),
            0);
  EXPECT_NE(log.find("different scene"), std::string::npos) << log;
}

TEST(RenderDataset, BadInputFailsClearlyAndWritesNothing) {
  TempDir dir;
  std::string log;
  EXPECT_EQ(
      run_simcap("render " + (dir / "missing.yaml").string() + " -o " + (dir / "out").string(),
                 &log),
      1);
  EXPECT_NE(log.find("missing.yaml"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "out"));

  std::ofstream(dir / "broken.bvh") << "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n";
  EXPECT_EQ(run_simcap("render " + scene_path("studio4") + " -o " + (dir / "out").string() +
                           " --motion " + (dir / "broken.bvh").string(),
                       &log),
            1);
  EXPECT_NE(log.find("broken.bvh"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "out"));

  EXPECT_EQ(run_simcap("render " + scene_path("studio4") + " -o /proc/simcap_cannot_write", &log),
            1);
  EXPECT_NE(log.find("/proc/simcap_cannot_write"), std::string::npos) << log;

  std::ofstream(dir / "file") << "x";
  EXPECT_EQ(run_simcap("render " + scene_path("studio4") + " -o " + (dir / "file").string(), &log),
            1);
  EXPECT_NE(log.find("not a folder"), std::string::npos) << log;

  fs::create_directories(dir / "busy");
  std::ofstream(dir / "busy" / "notes.txt") << "keep me";
  EXPECT_EQ(run_simcap("render " + scene_path("studio4") + " -o " + (dir / "busy").string(), &log),
            1);
  EXPECT_NE(log.find("not empty"), std::string::npos) << log;
  EXPECT_EQ(run_simcap("render " + scene_path("studio4") + " -o " + (dir / "busy").string() +
                           " --overwrite",
                       &log),
            1);
  EXPECT_EQ(read_text(dir / "busy" / "notes.txt"), "keep me");
  EXPECT_EQ(fs::directory_iterator(dir / "busy")->path().filename(), "notes.txt");
}

}  // namespace
}  // namespace simcap
