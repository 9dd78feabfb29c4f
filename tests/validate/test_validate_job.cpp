// validate_dataset on small datasets written by the test: the files it writes, the metrics in
// them, determinism, and a clear Error for each kind of mismatched or missing input.
#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "core/atomic_file.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"
#include "tests/validate/synthetic_dataset.h"
#include "validate/validate_job.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::TempDir;
using testing::write_synthetic_dataset;
using testing::write_track;

const auto kShift = [](int, const std::string&, const Eigen::Vector3d& p) {
  return Eigen::Vector3d(p + Eigen::Vector3d(0.03, 0.04, 0.0));
};

ValidateOptions quiet_options() {
  ValidateOptions o;
  o.quiet = true;
  o.video_max_frames = 6;
  return o;
}

std::string validate_error(const fs::path& dataset, const fs::path& track, const fs::path& out,
                           bool media = false) {
  ValidateOptions o = quiet_options();
  o.media = media;
  return error_of([&] { validate_dataset(dataset, track, out, o); });
}

// Rewrites `file` with every line passed through `edit` (returning false drops the line).
void edit_lines(const fs::path& file, const std::function<bool(std::string&)>& edit) {
  std::ifstream in(file);
  std::string text, line;
  while (std::getline(in, line)) {
    if (edit(line)) text += line + "\n";
  }
  write_text_atomic(file, text);
}

TEST(ValidateJob, WritesMetricsReportAndVideo) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  const ValidateSummary s =
      validate_dataset(dir / "data", dir / "track", dir / "report", quiet_options());
  EXPECT_NEAR(s.evaluation.mpjpe_mm, 50.0, 1e-3);

  const auto json = nlohmann::json::parse(read_text(dir / "report" / "metrics.json"));
  EXPECT_EQ(json["schema"], "simcap-metrics/1");
  EXPECT_NEAR(json["mpjpe_mm"].get<double>(), 50.0, 1e-3);
  EXPECT_NEAR(json["pa_mpjpe_mm"].get<double>(), 0.0, 1e-3);
  EXPECT_EQ(json["frame_count"], 12);
  EXPECT_EQ(json["joints"].size(), 16u);  // HE15 and skull_tip, which both sides have
  EXPECT_EQ(json["per_frame"].size(), 12u);
  EXPECT_EQ(json["per_joint"].size(), 16u);
  EXPECT_EQ(json["visibility"]["camera_count"], 3);
  // l_elbow is self-occluded in one camera, r_knee scene-occluded in one: 12 frames each.
  EXPECT_EQ(json["visibility"]["by_occlusion"][1]["occlusion"], "self_occluded");
  EXPECT_EQ(json["visibility"]["by_occlusion"][1]["count"], 12);
  EXPECT_EQ(json["visibility"]["by_occlusion"][2]["count"], 12);
  EXPECT_EQ(json["visibility"]["by_visible_cameras"][2]["count"], 24);
  EXPECT_EQ(json["failures"]["failed_frames"], 0);
  EXPECT_TRUE(json["angles"].is_null());
  EXPECT_EQ(json["media"]["overlay_frames"].size(), 2u);  // the worst frame is also the first

  const std::string html = read_text(dir / "report" / "report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("data:image/jpeg;base64,"), std::string::npos);
  EXPECT_NE(html.find("MPJPE per joint"), std::string::npos);
  // Each inline SVG is well-formed XML.
  size_t count = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) {
    const size_t end = html.find("</svg>", at);
    ASSERT_NE(end, std::string::npos);
    pugi::xml_document doc;
    EXPECT_TRUE(doc.load_string(html.substr(at, end + 6 - at).c_str())) << at;
    ++count;
  }
  EXPECT_EQ(count, 4u);  // per frame, per joint, by cameras, by occlusion

  if (json["media"]["video"].is_null()) {
    EXPECT_NE(html.find("No video"), std::string::npos);
  } else {
    EXPECT_GT(fs::file_size(dir / "report" / json["media"]["video"].get<std::string>()), 0u);
    EXPECT_NE(html.find("<video"), std::string::npos);
  }
}

TEST(ValidateJob, OutputIsDeterministic) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, [](int f, const std::string&, const Eigen::Vector3d& p) {
    return Eigen::Vector3d(p + Eigen::Vector3d(0.01 * (f % 5), 0.0, 0.0));
  });
  validate_dataset(dir / "data", dir / "track", dir / "a", quiet_options());
  validate_dataset(dir / "data", dir / "track", dir / "b", quiet_options());
  for (const char* file : {"metrics.json", "report.html"}) {
    EXPECT_EQ(read_text(dir / "a" / file), read_text(dir / "b" / file)) << file;
  }
}

TEST(ValidateJob, FailuresAndAngles) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  // Frames 4 and 5 are 200 mm off.
  write_track(dir / "track", d.truth, [](int f, const std::string&, const Eigen::Vector3d& p) {
    return Eigen::Vector3d(p + Eigen::Vector3d(0.0, f == 4 || f == 5 ? 0.2 : 0.0, 0.0));
  });
  std::string gt = "frame,joint,qw,qx,qy,qz\n", tracked = gt;
  for (int f = 0; f < 12; ++f) {
    gt += std::to_string(f) + ",l_elbow,1,0,0,0\n";
    const double h = 0.05 * (f % 2);  // half of 0.1 rad, every other frame
    tracked += std::to_string(f) + ",l_elbow," + std::to_string(std::cos(h)) + "," +
               std::to_string(std::sin(h)) + ",0,0\n";
  }
  write_text_atomic(dir / "data" / "gt" / "angles.csv", gt);
  write_text_atomic(dir / "track" / "angles.csv", tracked);
  ValidateOptions o = quiet_options();
  o.media = false;
  const auto ev = validate_dataset(dir / "data", dir / "track", dir / "r", o).evaluation;
  EXPECT_EQ(ev.failures.failed_frames, 2);
  ASSERT_EQ(ev.failures.episodes.size(), 1u);
  EXPECT_EQ(ev.failures.episodes[0].first_frame, 4);
  EXPECT_EQ(ev.failures.episodes[0].frames, 2);
  ASSERT_EQ(ev.angles.size(), 1u);
  EXPECT_NEAR(ev.angles[0].rmse_rad, std::sqrt(0.01 / 2), 1e-6);
  EXPECT_NE(read_text(dir / "r" / "report.html").find("Joint angles"), std::string::npos);
}

TEST(ValidateJob, DifferentFrameRangesAreNamed) {
  TempDir dir;
  write_synthetic_dataset(dir / "data", 12);
  const auto other = write_synthetic_dataset(dir / "other", 8, 6);
  write_track(dir / "track", other.truth, kShift);
  const std::string e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("track/joints3d.csv"), std::string::npos) << e;
  EXPECT_NE(e.find("8 frames (6 to 13)"), std::string::npos) << e;
  EXPECT_NE(e.find("12 frames (0 to 11)"), std::string::npos) << e;
  EXPECT_NE(e.find("frame 12 is not in the ground truth"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir / "r" / "metrics.json"));
}

TEST(ValidateJob, TrackMissingFramesIsNamed) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  edit_lines(dir / "track" / "joints3d.csv", [](std::string& l) { return l.rfind("7,", 0) != 0; });
  const std::string e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("no rows for frame 7"), std::string::npos) << e;
}

TEST(ValidateJob, ATrackOfTheFirstFramesIsScoredOnThem) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data", 12);
  write_track(dir / "track", d.truth, kShift);
  // What `simcap track --frames 5` writes: frames 0 to 4 (and the header).
  edit_lines(dir / "track" / "joints3d.csv",
             [](std::string& l) { return !std::isdigit(l[0]) || std::stoi(l) < 5; });
  ValidateOptions o = quiet_options();
  o.media = false;
  const auto ev = validate_dataset(dir / "data", dir / "track", dir / "r", o).evaluation;
  EXPECT_EQ(ev.frames, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_NEAR(ev.mpjpe_mm, 50.0, 1e-3);

  // Frames that do not start where the ground truth does are no such track.
  write_track(dir / "track", d.truth, kShift);
  edit_lines(dir / "track" / "joints3d.csv",
             [](std::string& l) { return !std::isdigit(l[0]) || std::stoi(l) >= 3; });
  const std::string e = validate_error(dir / "data", dir / "track", dir / "r2");
  EXPECT_NE(e.find("no rows for frame 0"), std::string::npos) << e;
  EXPECT_NE(e.find("--frames N"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir / "r2" / "metrics.json"));
}

TEST(ValidateJob, MissingJointsAreNamed) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  edit_lines(dir / "track" / "joints3d.csv",
             [](std::string& l) { return l.find(",l_knee,") == std::string::npos; });
  std::string e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("track/joints3d.csv"), std::string::npos) << e;
  EXPECT_NE(e.find("missing l_knee"), std::string::npos) << e;
  EXPECT_NE(e.find("HE15"), std::string::npos) << e;

  // A joint present in some frames only.
  write_track(dir / "track", d.truth, kShift);
  edit_lines(dir / "track" / "joints3d.csv",
             [](std::string& l) { return l.rfind("3,vc7,", 0) != 0; });
  e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("frame 3 has no row for joint 'vc7'"), std::string::npos) << e;
}

TEST(ValidateJob, WrongFoldersAreNamed) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  std::string e = validate_error(dir / "track", dir / "data", dir / "r");
  EXPECT_NE(e.find("the order is DATASET TRACK"), std::string::npos) << e;
  e = validate_error(dir / "data", dir / "data", dir / "r");
  EXPECT_NE(e.find("this is a dataset, not a track"), std::string::npos) << e;
  e = validate_error(dir / "nowhere", dir / "track", dir / "r");
  EXPECT_NE(e.find("nowhere: not a folder"), std::string::npos) << e;
  e = validate_error(dir / "data", dir / "empty", dir / "r");
  EXPECT_NE(e.find("empty: not a folder"), std::string::npos) << e;
  // simcap loop's output folder in place of its dataset or its track.
  fs::create_directories(dir / "loop" / "dataset");
  fs::create_directories(dir / "loop" / "track");
  e = validate_error(dir / "loop", dir / "track", dir / "r");
  EXPECT_NE(e.find("not a dataset; its dataset is " + (dir / "loop" / "dataset").string()),
            std::string::npos)
      << e;
  e = validate_error(dir / "data", dir / "loop", dir / "r");
  EXPECT_NE(e.find("not a track; its track is " + (dir / "loop" / "track").string()),
            std::string::npos)
      << e;
}

TEST(ValidateJob, AReportIsNotWrittenIntoADatasetOrATrack) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  std::string e = validate_error(dir / "data", dir / "track", dir / "data");
  EXPECT_NE(e.find("data: holds a dataset"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir / "data" / "metrics.json"));
  e = validate_error(dir / "data", dir / "track", dir / "track");
  EXPECT_NE(e.find("track: holds a track (joints3d.csv)"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir / "track" / "metrics.json"));
  // An earlier report is replaced.
  ValidateOptions o = quiet_options();
  o.media = false;
  validate_dataset(dir / "data", dir / "track", dir / "r", o);
  EXPECT_NO_THROW(validate_dataset(dir / "data", dir / "track", dir / "r", o));
}

TEST(ValidateJob, MissingFilesAreNamed) {
  for (const char* file : {"gt/joints2d.csv", "calibration/opencv.yaml", "gt/joints3d.csv"}) {
    TempDir dir;
    const auto d = write_synthetic_dataset(dir / "data");
    write_track(dir / "track", d.truth, kShift);
    fs::remove(dir / "data" / file);
    const std::string e = validate_error(dir / "data", dir / "track", dir / "r");
    EXPECT_NE(e.find(std::string(file) + ": missing; expected"), std::string::npos) << e;
  }
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  fs::create_directories(dir / "track");
  std::string e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("track/joints3d.csv: missing; expected"), std::string::npos) << e;

  write_track(dir / "track", d.truth, kShift);
  fs::remove(rgb_frame_path(dir / "data", "cam01", 0));
  e = validate_error(dir / "data", dir / "track", dir / "r", true);
  EXPECT_NE(e.find("cam01/rgb/000000.png: missing"), std::string::npos) << e;
  EXPECT_NE(e.find("--no-media"), std::string::npos) << e;
  EXPECT_EQ(validate_error(dir / "data", dir / "track", dir / "r", false), "<no error>");

  write_text_atomic(dir / "track" / "angles.csv", "frame,joint,qw,qx,qy,qz\n0,l_elbow,1,0,0,0\n");
  e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("gt/angles.csv: missing; expected the ground-truth joint rotations"),
            std::string::npos)
      << e;
}

TEST(ValidateJob, UnknownVideoCameraIsNamed) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  ValidateOptions o = quiet_options();
  o.video_camera = "cam07";
  const std::string e =
      error_of([&] { validate_dataset(dir / "data", dir / "track", dir / "r", o); });
  EXPECT_EQ(e.rfind("--video-camera: ", 0), 0u) << e;
  EXPECT_NE(e.find("opencv.yaml: unknown camera 'cam07'"), std::string::npos) << e;
  EXPECT_FALSE(fs::exists(dir / "r"));
}

TEST(ValidateJob, BadVisibilityTablesAreNamed) {
  TempDir dir;
  const auto d = write_synthetic_dataset(dir / "data");
  write_track(dir / "track", d.truth, kShift);
  const fs::path file = dir / "data" / "gt" / "joints2d.csv";
  const std::string original = read_text(file);

  edit_lines(file, [n = 0](std::string& l) mutable {
    if (++n == 5) l.replace(l.rfind(',') + 1, std::string::npos, "hidden");
    return true;
  });
  std::string e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("joints2d.csv:5: column 'visibility': expected visible"), std::string::npos)
      << e;

  write_text_atomic(file, original);
  edit_lines(file, [](std::string& l) {
    if (l.rfind("2,cam02,", 0) == 0) l.replace(2, 5, "cam09");
    return true;
  });
  e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("unknown camera 'cam09'; the calibration has cam00, cam01, cam02"),
            std::string::npos)
      << e;

  write_text_atomic(file, original);
  edit_lines(file, [](std::string& l) { return l.rfind("9,cam01,r_hip,", 0) != 0; });
  e = validate_error(dir / "data", dir / "track", dir / "r");
  EXPECT_NE(e.find("no row for joint 'r_hip' in camera cam01 at frame 9"), std::string::npos) << e;
}

}  // namespace
}  // namespace simcap
