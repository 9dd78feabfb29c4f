// Sweep files: parsing, expansion into points, bad files, and the tables and plot written for a
// sweep run through a stand-in closed loop (so that the test needs neither renderer nor tracker).
#include <gtest/gtest.h>

#include <pugixml.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/error.h"
#include "models/humanoid.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"
#include "validate/sweep.h"
#include "validate/visibility.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::TempDir;

// A sweep file next to an (empty) scene file, which is all that load_sweep looks at.
fs::path write_sweep(const TempDir& dir, const std::string& text) {
  write_text_atomic(dir / "scenes" / "room.yaml", "# a scene\n");
  write_text_atomic(dir / "scenes" / "other.yaml", "# another scene\n");
  write_text_atomic(dir / "stress" / "sweep.yaml", text);
  return dir / "stress" / "sweep.yaml";
}

const char* kTwoAxes = R"(title: Test sweep
scene: ../scenes/room.yaml
frames: 30
seed: 7
set:
  room.size: [6, 3, 6]
  rig.type: ring
track: {method: moschini, init: gt}
vary:
  - name: cameras
    parameter: rig.count
    values: [2, 4]
  - name: masks
    cases:
      - {label: exact, track.silhouettes: gt}
      - {track.silhouettes: bgsub, noise.rgb_sigma: 8}
)";

TEST(Sweep, ExpandsEveryCombination) {
  TempDir dir;
  const SweepSpec spec = load_sweep(write_sweep(dir, kTwoAxes));
  EXPECT_EQ(spec.title, "Test sweep");
  ASSERT_EQ(spec.axes.size(), 2u);
  EXPECT_TRUE(spec.axes[0].numeric());
  EXPECT_FALSE(spec.axes[1].numeric());
  EXPECT_EQ(spec.axes[1].labels[1], "track.silhouettes=bgsub noise.rgb_sigma=8");
  const auto points = sweep_points(spec);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[1].labels,
            (std::vector<std::string>{"2", "track.silhouettes=bgsub noise.rgb_sigma=8"}));
  const LoopConfig& c = points[1].config;
  EXPECT_EQ(c.scene, (dir / "scenes" / "room.yaml").lexically_normal());
  EXPECT_EQ(c.frames, 30);
  EXPECT_EQ(c.seed, 7u);
  EXPECT_EQ(c.scene_overrides, (std::vector<std::string>{"room.size=[6, 3, 6]", "rig.type=ring",
                                                         "rig.count=2", "noise.rgb_sigma=8"}));
  using Option = std::pair<std::string, std::string>;
  EXPECT_EQ(
      c.track_options,
      (std::vector<Option>{{"method", "moschini"}, {"init", "gt"}, {"silhouettes", "bgsub"}}));
  EXPECT_EQ(points[2].config.scene_overrides[2], "rig.count=4");
  EXPECT_EQ(sweep_point_folder(3, points[3]), "03_4_track.silhouettes_bgsub_noise.rgb_sigma_8");
}

TEST(Sweep, SceneCanBeTheVariedParameter) {
  TempDir dir;
  const SweepSpec spec = load_sweep(write_sweep(dir, R"(frames: 10
vary:
  - name: scene
    cases:
      - {label: plain, scene: ../scenes/room.yaml}
      - {label: other, scene: ../scenes/other.yaml}
)"));
  const auto points = sweep_points(spec);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].config.scene.filename(), "other.yaml");
  EXPECT_EQ(points[1].labels[0], "other");
}

TEST(Sweep, DetectorIsABaseSettingOrAnAxis) {
  TempDir dir;
  const auto points = sweep_points(load_sweep(write_sweep(dir, R"(scene: ../scenes/room.yaml
track: {method: triangulate}
detector: {name: truth-noise, noise_px: 2, seed: 5}
vary:
  - name: detector
    cases:
      - {label: noisier, detector.noise_px: 4}
      - {label: mp, detector.name: mediapipe}
)")));
  ASSERT_EQ(points.size(), 2u);
  const DetectorConfig& a = points[0].config.detector;
  EXPECT_EQ(a.name, "truth-noise");
  EXPECT_EQ(a.line, 3);
  EXPECT_EQ(a.noise_px, 4.0);
  EXPECT_EQ(a.seed, 5u);
  const DetectorConfig& b = points[1].config.detector;
  EXPECT_EQ(b.name, "mediapipe");
  EXPECT_EQ(b.line, 8);
  EXPECT_EQ(b.noise_px, 2.0);
  // A scalar names the detector alone.
  const auto plain = sweep_points(load_sweep(write_sweep(
      dir,
      "scene: ../scenes/room.yaml\ndetector: mediapipe\nvary: [{parameter: frames, values: "
      "[2]}]\n")));
  EXPECT_EQ(plain[0].config.detector.name, "mediapipe");
  EXPECT_EQ(plain[0].config.detector.line, 2);
}

TEST(Sweep, BadFilesAreNamed) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"scene: ../scenes/room.yaml\nframs: 3\nvary: [{parameter: rig.count, values: [1]}]\n",
       "sweep.yaml:2: frams: unknown key"},
      {"scene: ../scenes/room.yaml\nframes: 0\nvary: [{parameter: rig.count, values: [1]}]\n",
       "sweep.yaml:2: frames: expected a positive integer"},
      {"scene: ../scenes/nope.yaml\nvary: [{parameter: rig.count, values: [1]}]\n",
       "sweep.yaml:1: scene: no such file"},
      {"scene: ../scenes/room.yaml\n", "sweep.yaml: vary: missing"},
      {"frames: 3\nvary: [{parameter: rig.count, values: [1]}]\n", "sweep.yaml: scene: missing"},
      {"scene: ../scenes/room.yaml\nvary:\n  - parameter: rig.count\n    cases: []\n",
       "sweep.yaml:3: vary: expected either parameter and values, or cases"},
      {"scene: ../scenes/room.yaml\nvary:\n  - parameter: frames\n    values: [10, x]\n",
       "sweep.yaml:4: frames: expected a positive integer"},
      {"scene: ../scenes/room.yaml\nvary:\n  - cases:\n    - {label: a}\n",
       "sweep.yaml:4: cases: a case sets nothing"},
      {"scene: ../scenes/room.yaml\nvary:\n  - parameter: set\n    values: [1]\n",
       "sweep.yaml:4: set: cannot be varied"},
      {"scene: [unclosed\n", "sweep.yaml:"},
      {"scene: ../scenes/room.yaml\ndetector:\n  name: mediapipe\n  noise: 2\n"
       "vary: [{parameter: rig.count, values: [1]}]\n",
       "sweep.yaml:4: detector.noise: unknown detector key; expected name, noise_px or seed"},
      {"scene: ../scenes/room.yaml\nvary:\n  - parameter: detector.noise_px\n    values: [1, -2]\n",
       "sweep.yaml:4: detector.noise_px: expected a number >= 0"},
      {"scene: ../scenes/room.yaml\ndetector: {name: truth-noise, seed: x}\n"
       "vary: [{parameter: rig.count, values: [1]}]\n",
       "sweep.yaml:2: detector.seed: expected a non-negative integer"},
      {"scene: ../scenes/room.yaml\ndetector: [mediapipe]\nvary: [{parameter: rig.count, values: "
       "[1]}]\n",
       "sweep.yaml:2: detector: expected a map of key: value"},
  };
  for (const auto& [text, expected] : cases) {
    TempDir dir;
    const std::string e = error_of([&] { load_sweep(write_sweep(dir, text)); });
    EXPECT_NE(e.find(expected), std::string::npos) << text << "\n-> " << e;
  }
  TempDir dir;
  EXPECT_NE(error_of([&] { load_sweep(dir / "none.yaml"); }).find("none.yaml: no such sweep file"),
            std::string::npos);
}

TEST(Sweep, ShippedSweepsLoad) {
  int shipped = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SIMCAP_SOURCE_DIR) / "stress")) {
    if (entry.path().extension() != ".yaml") continue;
    const SweepSpec spec = load_sweep(entry.path());
    EXPECT_GE(sweep_points(spec).size(), 2u) << entry.path();
    ++shipped;
  }
  EXPECT_GE(shipped, 15);
  const auto cameras =
      sweep_points(load_sweep(fs::path(SIMCAP_SOURCE_DIR) / "stress" / "cameras.yaml"));
  ASSERT_EQ(cameras.size(), 5u);
  EXPECT_EQ(cameras[4].config.scene_overrides.back(), "rig.count=8");
  // 4 cameras x 6 motions x 4 particle counts, the particle count varying fastest.
  const auto monocular =
      sweep_points(load_sweep(fs::path(SIMCAP_SOURCE_DIR) / "stress" / "monocular.yaml"));
  ASSERT_EQ(monocular.size(), 96u);
  EXPECT_EQ(monocular[1].labels, (std::vector<std::string>{"front 2.6 m", "raise", "200"}));
  // 5 camera counts x 2 detectors, the detector varying fastest.
  const auto detectors =
      sweep_points(load_sweep(fs::path(SIMCAP_SOURCE_DIR) / "stress" / "detectors.yaml"));
  ASSERT_EQ(detectors.size(), 10u);
  EXPECT_EQ(detectors[0].config.detector.name, "truth-noise");
  EXPECT_EQ(detectors[0].config.detector.noise_px, 2.0);
  EXPECT_EQ(detectors[9].config.detector.name, "mediapipe");
  EXPECT_EQ(detectors[9].config.scene_overrides.back(), "rig.count=8");
}

// A stand-in loop: every joint is 90/count mm off along x; the count 3 point fails.
SweepOutcome fake_loop(const SweepPoint& point, const fs::path& dir) {
  const double count = std::stod(point.labels[0]);
  if (count == 3) throw Error("tracker: too few cameras, see log");
  EvaluationInput in;
  in.joints = he15_joints();
  Eigen::Matrix3Xd truth = Eigen::Matrix3Xd::Random(3, 15);
  in.frames = {0, 1};
  in.truth = {truth, truth};
  const Eigen::Matrix3Xd est = truth.colwise() + Eigen::Vector3d(0.09 / count, 0, 0);
  in.estimate = {est, est};
  SweepOutcome o;
  o.evaluation = evaluate(in);
  o.report = dir / "report" / "report.html";
  o.render_s = 1.5;
  o.track_s = count;  // 2 frames: 1 frame/s with 2 cameras, 0.5 with 4
  return o;
}

TEST(Sweep, RunWritesTablesAndPlot) {
  TempDir dir;
  const SweepSpec spec = load_sweep(write_sweep(dir, R"(title: Cameras
scene: ../scenes/room.yaml
vary:
  - {name: cameras, parameter: rig.count, values: [2, 3, 4]}
)"));
  const auto outcomes = run_sweep(spec, dir / "out", fake_loop, true);
  ASSERT_EQ(outcomes.size(), 3u);
  EXPECT_FALSE(outcomes[1].evaluation);

  CsvReader csv(dir / "out" / "table.csv",
                {"point", "cameras", "status", "frames", "mpjpe_mm", "pa_mpjpe_mm", "pck_50mm",
                 "pck_100mm", "pck_150mm", "rmse_mean_mm", "wrists_elbows_mm", "failed_fraction",
                 "worst_joint", "worst_joint_mm", "report"});
  ASSERT_TRUE(csv.next());
  EXPECT_EQ(csv.text(1), "2");
  EXPECT_EQ(csv.text(2), "ok");
  EXPECT_NEAR(csv.number(4), 45.0, 0.01);
  EXPECT_NEAR(csv.number(6), 1.0, 1e-9);
  EXPECT_EQ(csv.text(12), he15_joints().front());  // every joint is as far off: the first
  EXPECT_NEAR(csv.number(13), 45.0, 0.01);
  EXPECT_EQ(csv.text(14), "points/00_2/report/report.html");
  ASSERT_TRUE(csv.next());
  EXPECT_EQ(csv.text(2), "error: tracker: too few cameras; see log");
  ASSERT_TRUE(csv.next());
  EXPECT_NEAR(csv.number(4), 22.5, 0.01);
  EXPECT_FALSE(csv.next());

  pugi::xml_document svg;
  ASSERT_TRUE(svg.load_file((dir / "out" / "mpjpe.svg").c_str()));
  EXPECT_STREQ(svg.first_child().name(), "svg");
  const std::string html = read_text(dir / "out" / "table.html");
  EXPECT_NE(html.find("<h1>Cameras</h1>"), std::string::npos);
  EXPECT_NE(html.find("href=\"points/02_4/report/report.html\""), std::string::npos);
  EXPECT_NE(html.find("failed: tracker: too few cameras, see log"), std::string::npos);
  EXPECT_NE(html.find("<th colspan=\"2\">worst</th>"), std::string::npos);
  CsvReader times(dir / "out" / "timings.csv",
                  {"point", "render_s", "track_s", "validate_s", "track_frames_per_s"});
  ASSERT_TRUE(times.next());
  EXPECT_NEAR(times.number(4), 1.0, 1e-9);

  // The printed table: a row per point, the mean over the points that ran and the worst value of
  // each column (largest error, fewest frames/s).
  const std::string text = sweep_table_text(spec, sweep_points(spec), outcomes);
  const auto row = [&](const std::string& start) {
    const size_t at = text.find("\n  " + start + " ");
    if (at == std::string::npos) return std::string();
    return text.substr(at + 1, text.find('\n', at + 1) - at - 1);
  };
  const auto words = [](const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> w;
    for (std::string x; in >> x;) w.push_back(x);
    return w;
  };
  const std::string joint = he15_joints().front();
  EXPECT_EQ(words(row("2")),
            (std::vector<std::string>{"2", "45.0", "0.0", "100.0%", "0.0%", joint, "45.0", "1.0"}))
      << text;
  EXPECT_NE(row("3").find("failed: tracker: too few cameras"), std::string::npos) << text;
  // The means 33.75 mm and 0.75 frames/s are printed with one decimal, either way.
  std::vector<std::string> mean = words(row("mean"));
  ASSERT_EQ(mean.size(), 7u) << text;
  EXPECT_NEAR(std::stod(mean[1]), 33.75, 0.051);
  EXPECT_NEAR(std::stod(mean[5]), 33.75, 0.051);
  EXPECT_NEAR(std::stod(mean[6]), 0.75, 0.051);
  mean[1] = mean[5] = mean[6] = "";
  EXPECT_EQ(mean, (std::vector<std::string>{"mean", "", "0.0", "100.0%", "0.0%", "", ""}));
  EXPECT_EQ(words(row("worst")), (std::vector<std::string>{"worst", "45.0", "0.0", "100.0%", "0.0%",
                                                           joint, "45.0", "0.5"}))
      << text;
}

// A stand-in loop with a 2D detector: 10 visible keypoints, 8 detected 3 px off; 4
// scene-occluded ones, 2 detected 9 px off.
SweepOutcome fake_detector_loop(const SweepPoint& point, const fs::path& dir) {
  SweepOutcome o = fake_loop(point, dir);
  KeypointScores k;
  k.coco.ap = 0.5;
  KeypointGroup& visible = k.by_visibility[static_cast<int>(VisibilityLabel::visible)];
  visible.keypoints = 10;
  visible.detected = 8;
  visible.errors_px.assign(8, 3.0);
  KeypointGroup& hidden = k.by_visibility[static_cast<int>(VisibilityLabel::scene_occluded)];
  hidden.keypoints = 4;
  hidden.detected = 2;
  hidden.errors_px.assign(2, 9.0);
  k.all.add(visible);
  k.all.add(hidden);
  o.keypoints2d = k;
  o.report2d = dir / "report2d" / "report.html";
  return o;
}

TEST(Sweep, DetectorPointsHave2dColumns) {
  TempDir dir;
  const SweepSpec spec = load_sweep(write_sweep(dir, R"(scene: ../scenes/room.yaml
track: {method: triangulate}
detector: truth-noise
vary:
  - {name: cameras, parameter: rig.count, values: [2, 3]}
)"));
  const auto outcomes = run_sweep(spec, dir / "out", fake_detector_loop, true);
  std::vector<std::string> columns = {
      "point",       "cameras",        "status",           "frames",
      "mpjpe_mm",    "pa_mpjpe_mm",    "pck_50mm",         "pck_100mm",
      "pck_150mm",   "rmse_mean_mm",   "wrists_elbows_mm", "failed_fraction",
      "worst_joint", "worst_joint_mm", "report",           "ap_2d"};
  for (const char* c : {"in_frame", "visible", "self_occluded", "scene_occluded"}) {
    for (const char* m : {"_miss_rate", "_median_px", "_pck_torso_0.2", "_swap_rate"}) {
      columns.push_back(std::string(c) + m);
    }
  }
  columns.push_back("report2d");
  CsvReader csv(dir / "out" / "table.csv", columns);
  ASSERT_TRUE(csv.next());
  EXPECT_NEAR(csv.number(15), 0.5, 1e-9);
  EXPECT_NEAR(csv.number(16), 4.0 / 14, 1e-4);  // in frame: 4 of 14 missed
  EXPECT_NEAR(csv.number(17), 3.0, 1e-9);       // median of eight 3s and two 9s
  EXPECT_NEAR(csv.number(20), 0.2, 1e-9);       // visible: 2 of 10 missed
  EXPECT_NEAR(csv.number(21), 3.0, 1e-9);
  EXPECT_EQ(csv.text(24), "");  // no self-occluded keypoint: empty cells
  EXPECT_NEAR(csv.number(28), 0.5, 1e-9);
  EXPECT_NEAR(csv.number(29), 9.0, 1e-9);
  EXPECT_EQ(csv.text(32), "points/00_2/report2d/report.html");
  ASSERT_TRUE(csv.next());  // the failed point keeps the columns, empty
  EXPECT_EQ(csv.text(2), "error: tracker: too few cameras; see log");
  EXPECT_EQ(csv.text(15), "");
  EXPECT_FALSE(csv.next());

  const std::string html = read_text(dir / "out" / "table.html");
  EXPECT_NE(html.find("2D keypoints of the detector"), std::string::npos);
  EXPECT_NE(html.find("href=\"points/00_2/report2d/report.html\""), std::string::npos);
  EXPECT_NE(html.find("detector truth-noise (2.0 px, seed 1)"), std::string::npos);
  const std::string text = sweep_table_text(spec, sweep_points(spec), outcomes);
  EXPECT_NE(text.find("px scene"), std::string::npos) << text;
  const size_t row = text.find("\n  2 ", text.find("2D keypoints"));
  ASSERT_NE(row, std::string::npos) << text;
  std::istringstream in(text.substr(row, text.find('\n', row + 1) - row));
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  EXPECT_EQ(w, (std::vector<std::string>{"2", "0.500", "3.00", "3.00", "-", "9.00", "28.6%",
                                         "20.0%", "-", "50.0%", "-"}))
      << text;
}

// A stand-in one-camera loop: the camera far along -x, so fake_loop's error (along x) is all
// along its rays.
SweepOutcome fake_one_camera_loop(const SweepPoint& point, const fs::path& dir) {
  SweepOutcome o = fake_loop(point, dir);
  const double along = o.evaluation->mpjpe_mm;
  o.evaluation->ray = RaySplit{along, 0.0};
  return o;
}

TEST(Sweep, OneCameraPointsSplitTheErrorAlongAndAcrossTheRay) {
  TempDir dir;
  const SweepSpec spec = load_sweep(write_sweep(dir, R"(scene: ../scenes/room.yaml
track: {method: monocular}
vary:
  - {name: cameras, parameter: rig.count, values: [2, 3]}
)"));
  const auto outcomes = run_sweep(spec, dir / "out", fake_one_camera_loop, true);
  CsvReader csv(dir / "out" / "table.csv",
                {"point", "cameras", "status", "frames", "mpjpe_mm", "pa_mpjpe_mm", "pck_50mm",
                 "pck_100mm", "pck_150mm", "rmse_mean_mm", "wrists_elbows_mm", "failed_fraction",
                 "worst_joint", "worst_joint_mm", "report", "along_ray_mm", "across_ray_mm"});
  ASSERT_TRUE(csv.next());
  EXPECT_NEAR(csv.number(15), 45.0, 0.01);
  EXPECT_NEAR(csv.number(16), 0.0, 1e-9);
  ASSERT_TRUE(csv.next());  // the failed point keeps the columns, empty
  EXPECT_EQ(csv.text(15), "");
  EXPECT_FALSE(csv.next());
  const std::string html = read_text(dir / "out" / "table.html");
  EXPECT_NE(html.find("<h2>Depth ambiguity</h2>"), std::string::npos);
  EXPECT_NE(html.find("Error along and across the camera ray against cameras"), std::string::npos);
  const std::string text = sweep_table_text(spec, sweep_points(spec), outcomes);
  const size_t row = text.find("\n  2 ", text.find("Depth ambiguity"));
  ASSERT_NE(row, std::string::npos) << text;
  EXPECT_EQ(text.substr(row + 1, text.find('\n', row + 1) - row - 1),
            "  2                             45.0       0.0")
      << text;
}

}  // namespace
}  // namespace simcap
