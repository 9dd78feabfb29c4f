// The validate, loop, demo and stress commands through the simcap program: exit statuses,
// --fail-above, messages naming bad inputs, and small closed loops and sweeps end to end.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "tests/support/temp_dir.h"
#include "tests/validate/synthetic_dataset.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

// Small images keep the closed-loop tests to a few seconds.
const std::string kSmall = " --set rig.resolution=[160,120] -q ";

std::string quoted(const fs::path& p) {
  return "'" + p.string() + "'";
}

TEST(ValidateCli, FailAboveSetsTheExitStatus) {
  TempDir dir;
  const auto d = testing::write_synthetic_dataset(dir / "data");
  testing::write_track(dir / "track", d.truth,
                       [](int, const std::string&, const Eigen::Vector3d& p) {
                         return Eigen::Vector3d(p + Eigen::Vector3d(0.03, 0.04, 0));
                       });
  const std::string args = "validate " + quoted(dir / "data") + " " + quoted(dir / "track") +
                           " -o " + quoted(dir / "report") + " -q --no-media";
  std::string out;
  EXPECT_EQ(run_simcap(args + " --fail-above 40", &out), 4) << out;
  EXPECT_NE(out.find("FAILED: MPJPE 50.0 mm is above --fail-above 40.0 mm"), std::string::npos)
      << out;
  EXPECT_EQ(run_simcap(args + " --fail-above 60", &out), 0) << out;
  EXPECT_NE(out.find("MPJPE"), std::string::npos);
  EXPECT_NE(out.find("report.html"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "report" / "metrics.json"));
}

TEST(ValidateCli, BadInputExitsOneNamingTheFile) {
  TempDir dir;
  testing::write_synthetic_dataset(dir / "data");
  fs::create_directories(dir / "track");
  std::string out;
  EXPECT_EQ(run_simcap("validate " + quoted(dir / "data") + " " + quoted(dir / "track") + " -o " +
                           quoted(dir / "report"),
                       &out),
            1);
  EXPECT_NE(out.find("simcap: error: "), std::string::npos) << out;
  EXPECT_NE(out.find("track/joints3d.csv: missing"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "report"));
}

TEST(ValidateCli, BadSweepFileExitsOne) {
  TempDir dir;
  write_text_atomic(dir / "sweep.yaml", "scene: nowhere.yaml\nvary: []\n");
  std::string out;
  EXPECT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out"), &out),
            1);
  EXPECT_NE(out.find("sweep.yaml:1: scene: no such file"), std::string::npos) << out;

  // An override the scene loader rejects stops the sweep before anything runs.
  write_text_atomic(dir / "sweep.yaml",
                    "scene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
                        "\nframes: 2\nvary: [{parameter: rig.cuont, values: [2]}]\n");
  EXPECT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out"), &out),
            1);
  // The error is the sweep file's, so it names that file and the override's line there.
  EXPECT_NE(out.find("sweep.yaml:3: " +
                     (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
                     ": override 'rig.cuont=2': rig.cuont: unknown key"),
            std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(dir / "out" / "table.csv"));

  write_text_atomic(dir / "sweep.yaml",
                    "scene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
                        "\nframes: 2\nvary: [{parameter: track.colour, values: [red]}]\n");
  EXPECT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out"), &out),
            1);
  EXPECT_NE(out.find("sweep.yaml:3: track.colour: unknown tracker option"), std::string::npos)
      << out;

  // A known option reaches the tracker, which names the bad value.
  write_text_atomic(dir / "sweep.yaml",
                    "scene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
                        "\nframes: 2\nvary: [{parameter: track.traversal, values: [sideways]}]\n");
  EXPECT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out"), &out),
            1);
  EXPECT_NE(out.find("sweep.yaml:3: track.traversal: --traversal: unknown value 'sideways'"),
            std::string::npos)
      << out;

  // A detector the loop does not know is named with its line, before anything runs.
  write_text_atomic(dir / "sweep.yaml",
                    "scene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
                        "\nframes: 2\ntrack: {method: triangulate}\nvary:\n  - name: det\n"
                        "    cases:\n      - {detector.name: truth-noise}\n"
                        "      - {detector.name: openpose}\n");
  EXPECT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out"), &out),
            1);
  EXPECT_NE(out.find("sweep.yaml:8: detector: unknown detector 'openpose'; expected none, "
                     "mediapipe or truth-noise"),
            std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(dir / "out" / "table.csv"));
  // ... and so is one with a tracker that reads the images.
  write_text_atomic(dir / "sweep.yaml",
                    "scene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
                        "\nframes: 2\ntrack: {method: moschini}\ndetector: truth-noise\n"
                        "vary: [{parameter: rig.count, values: [3]}]\n");
  EXPECT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out"), &out),
            1);
  EXPECT_NE(out.find("sweep.yaml:4: detector: track.method must be triangulate"), std::string::npos)
      << out;
}

TEST(LoopCli, RendersTracksAndValidates) {
  TempDir dir;
  std::string out;
  const fs::path scene = fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio4.yaml";
  ASSERT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "loop") +
                           " --frames 4 --no-media" + kSmall,
                       &out),
            0)
      << out;
  for (const char* word : {"render", "track", "validate", "MPJPE", "report.html"}) {
    EXPECT_NE(out.find(word), std::string::npos) << word << "\n" << out;
  }
  const auto json = nlohmann::json::parse(read_text(dir / "loop" / "report" / "metrics.json"));
  EXPECT_EQ(json["frame_count"], 4);
  EXPECT_TRUE(json["mpjpe_mm"].is_number());
  // The track records its dataset: validating it against another one is refused.
  testing::write_synthetic_dataset(dir / "other");
  EXPECT_EQ(run_simcap("validate " + quoted(dir / "other") + " " + quoted(dir / "loop" / "track") +
                           " -o " + quoted(dir / "wrong") + " -q --no-media",
                       &out),
            1);
  EXPECT_NE(out.find("dataset.txt:1: the track was made from another dataset"), std::string::npos)
      << out;
  EXPECT_FALSE(fs::exists(dir / "wrong"));
  // A second run replaces the first one's dataset.
  EXPECT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "loop") +
                           " --frames 3 --no-media" + kSmall,
                       &out),
            0)
      << out;
  EXPECT_EQ(
      nlohmann::json::parse(read_text(dir / "loop" / "report" / "metrics.json"))["frame_count"], 3);
}

TEST(LoopCli, DetectorTruthNoiseIsTriangulated) {
  TempDir dir;
  std::string out;
  const fs::path scene = fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio4.yaml";
  ASSERT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "loop") +
                           " --frames 3 --no-media --detector truth-noise --noise-px 1 -q",
                       &out),
            0)
      << out;
  for (const char* word : {"detect", "truth-noise", "MPJPE"}) {
    EXPECT_NE(out.find(word), std::string::npos) << word << "\n" << out;
  }
  EXPECT_TRUE(fs::exists(dir / "loop" / "detections.json"));
  const auto json = nlohmann::json::parse(read_text(dir / "loop" / "report" / "metrics.json"));
  EXPECT_EQ(json["frame_count"], 3);
  // 1 px of noise seen by 4 cameras 3-4 m away moves a triangulated joint by millimetres; the
  // rest is how far the COCO keypoints the family lifts lie from the H-Anim joints it scores.
  EXPECT_LT(json["mpjpe_mm"].get<double>(), 40.0);

  // A detector with a tracker that reads images is refused before anything is rendered.
  EXPECT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "bad") +
                           " --frames 2 --detector truth-noise --method moschini -q",
                       &out),
            1);
  EXPECT_NE(out.find("--method must be triangulate"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "bad" / "dataset"));
  // So is the triangulation without a detector: nothing would give it keypoints.
  EXPECT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "none") +
                           " --frames 2 --method triangulate -q",
                       &out),
            1);
  EXPECT_NE(out.find("needs 2D keypoints"), std::string::npos) << out;
  EXPECT_FALSE(fs::exists(dir / "none"));
}

// A person who walks out of every camera's view leaves frames the tracker only holds a pose
// for: the loop says how many, instead of scoring them as if they were tracked.
TEST(LoopCli, WarnsOfFramesWithoutThePerson) {
  TempDir dir;
  std::string out;
  const fs::path scene = fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio4.yaml";
  ASSERT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "loop") +
                           " --frames 45 --no-media --set 'actors[0].motion={procedural: "
                           "walk_path, speed: 3, radius: 4, duration: 4}'" +
                           kSmall,
                       &out),
            0)
      << out;
  EXPECT_NE(out.find("warning: no person in "), std::string::npos) << out;
  ASSERT_EQ(run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "stays") +
                           " --frames 3 --no-media" + kSmall,
                       &out),
            0)
      << out;
  EXPECT_EQ(out.find("warning:"), std::string::npos) << out;
}

// What the scene decides -- its cameras, its actors -- refuses a tracker before anything is
// rendered, with the refusal `simcap track` gives.
TEST(LoopCli, RefusesATrackerTheSceneCannotFeedBeforeRendering) {
  TempDir dir;
  std::string out;
  const fs::path scenes = fs::path(SIMCAP_SOURCE_DIR) / "scenes";
  const auto refused = [&](const fs::path& scene, const std::string& args) {
    const int status =
        run_simcap("loop " + quoted(scene) + " -o " + quoted(dir / "out") + " -q " + args, &out);
    EXPECT_FALSE(fs::exists(dir / "out")) << args;
    return status;
  };
  EXPECT_EQ(refused(scenes / "monocular.yaml", "--method moschini"), 1);
  EXPECT_NE(out.find("monocular.yaml: 1 camera, needs at least 2 for --method moschini"),
            std::string::npos)
      << out;
  EXPECT_EQ(refused(scenes / "monocular.yaml", "--method sik --effectors multiview"), 1);
  EXPECT_NE(out.find("needs at least 2 for --method sik --effectors multiview"), std::string::npos)
      << out;
  EXPECT_NE(out.find("use --method sik --effectors depth or mono (one camera), --method monocular "
                     "instead"),
            std::string::npos)
      << out;
  EXPECT_EQ(refused(scenes / "monocular.yaml", "--detector truth-noise"), 1);
  EXPECT_NE(out.find("for --method triangulate"), std::string::npos) << out;
  EXPECT_EQ(refused(scenes / "two_people.yaml", "--method monocular --actor actor1"), 1);
  EXPECT_NE(out.find("--actor actor1: --method monocular tracks only the first actor"),
            std::string::npos)
      << out;
  EXPECT_EQ(refused(scenes / "two_people.yaml", "--actor nobody"), 1);
  EXPECT_NE(out.find("--actor nobody: no such actor; the dataset has actor0, actor1"),
            std::string::npos)
      << out;
}

TEST(StressCli, SweepWritesOneRowPerPoint) {
  TempDir dir;
  write_text_atomic(
      dir / "sweep.yaml",
      "title: tiny\nscene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
          "\nframes: 3\nset: {rig.resolution: [160, 120]}\n"
          "vary:\n  - {name: cameras, parameter: rig.count, values: [3, 4]}\n"
          "  - name: masks\n    cases:\n      - {label: gt, track.silhouettes: gt}\n"
          "      - {label: bgsub, track.silhouettes: bgsub}\n");
  std::string out;
  ASSERT_EQ(
      run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out") + " -q",
                 &out),
      0)
      << out;
  CsvReader csv(dir / "out" / "table.csv",
                {"point", "cameras", "masks", "status", "frames", "mpjpe_mm", "pa_mpjpe_mm",
                 "pck_50mm", "pck_100mm", "pck_150mm", "rmse_mean_mm", "wrists_elbows_mm",
                 "failed_fraction", "worst_joint", "worst_joint_mm", "report"});
  int rows = 0;
  while (csv.next()) {
    EXPECT_EQ(csv.text(3), "ok") << csv.text(3);
    EXPECT_TRUE(fs::exists(dir / "out" / csv.text(15)));
    ++rows;
  }
  EXPECT_EQ(rows, 4);
  EXPECT_TRUE(fs::exists(dir / "out" / "mpjpe.svg"));
  EXPECT_TRUE(fs::exists(dir / "out" / "table.html"));
  // Datasets are removed unless --keep-datasets; the two tracker settings shared one render.
  EXPECT_FALSE(fs::exists(dir / "out" / "points" / "00_3_gt" / "dataset"));
  EXPECT_NE(out.find("tiny"), std::string::npos) << out;
  for (const char* word : {"worst joint", "frames/s", "\n  mean ", "\n  worst "}) {
    EXPECT_NE(out.find(word), std::string::npos) << word << "\n" << out;
  }
}

TEST(StressCli, TruthNoiseDetectorIsTriangulatedPerPoint) {
  TempDir dir;
  write_text_atomic(
      dir / "sweep.yaml",
      "scene: " + (fs::path(SIMCAP_SOURCE_DIR) / "scenes" / "studio8.yaml").string() +
          "\nframes: 3\nset: {rig.resolution: [160, 120]}\ntrack: {method: triangulate}\n"
          "vary:\n  - {name: cameras, parameter: rig.count, values: [3, 4]}\n"
          "  - name: detector\n    cases:\n"
          "      - {label: exact, detector.name: truth-noise, detector.noise_px: 0}\n"
          "      - {label: 2 px, detector.name: truth-noise, detector.noise_px: 2}\n");
  std::string out;
  ASSERT_EQ(run_simcap("stress " + quoted(dir / "sweep.yaml") + " -o " + quoted(dir / "out") +
                           " -q --frames 2",
                       &out),
            0)
      << out;
  EXPECT_NE(out.find("2D keypoints of the detector"), std::string::npos) << out;
  std::vector<std::string> columns = {"point",           "cameras",      "detector",
                                      "status",          "frames",       "mpjpe_mm",
                                      "pa_mpjpe_mm",     "pck_50mm",     "pck_100mm",
                                      "pck_150mm",       "rmse_mean_mm", "wrists_elbows_mm",
                                      "failed_fraction", "worst_joint",  "worst_joint_mm",
                                      "report",          "ap_2d"};
  for (const char* c : {"in_frame", "visible", "self_occluded", "scene_occluded"}) {
    for (const char* m : {"_miss_rate", "_median_px", "_pck_torso_0.2", "_swap_rate"}) {
      columns.push_back(std::string(c) + m);
    }
  }
  columns.push_back("report2d");
  const auto column = [&](const std::string& name) {
    return static_cast<int>(std::find(columns.begin(), columns.end(), name) - columns.begin());
  };
  CsvReader csv(dir / "out" / "table.csv", columns);
  int rows = 0;
  while (csv.next()) {
    EXPECT_EQ(csv.text(column("status")), "ok");
    EXPECT_EQ(csv.number(column("frames")), 2);  // --frames replaced the file's 3
    const double px = csv.number(column("visible_median_px"));
    // Exact keypoints are scored 0 px off; 2 px per coordinate is ~2.4 px (Rayleigh median).
    if (rows % 2 == 0) {
      EXPECT_EQ(px, 0.0);
      EXPECT_NEAR(csv.number(column("ap_2d")), 1.0, 1e-9);
    } else {
      EXPECT_GT(px, 1.0);
      EXPECT_LT(px, 4.0);
    }
    EXPECT_LT(csv.number(column("mpjpe_mm")), 60.0);
    EXPECT_TRUE(fs::exists(dir / "out" / csv.text(column("report2d"))));
    ++rows;
  }
  EXPECT_EQ(rows, 4);
}

}  // namespace
}  // namespace simcap
