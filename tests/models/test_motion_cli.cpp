// `simcap motion dump|retarget|generate` and load_motion: results that read back, errors that
// name file:line with a non-zero exit and no output file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "core/joint_track.h"
#include "models/bvh.h"
#include "models/foot_contact.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

const std::string kWalk = std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_01_start_walk_stop.bvh";

const char* kGood =
    "HIERARCHY\n"
    "ROOT Hips\n"
    "{\n"
    "  OFFSET 0 0 0\n"
    "  CHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n"
    "  JOINT Spine\n"
    "  {\n"
    "    OFFSET 0 10 0\n"
    "    CHANNELS 3 Zrotation Yrotation Xrotation\n"
    "    End Site\n"
    "    {\n"
    "      OFFSET 0 60 0\n"
    "    }\n"
    "  }\n"
    "}\n"
    "MOTION\n"
    "Frames: 2\n"
    "Frame Time: 0.01\n"
    "0 95 0 0 0 0 0 0 0\n"
    "1 95 0 0 10 0 0 0 5\n";

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

void write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

TEST(MotionCli, DumpWritesTheClipsOwnJoints) {
  testing::TempDir dir;
  write(dir / "good.bvh", kGood);
  std::string out;
  ASSERT_EQ(testing::run_simcap("motion dump " + (dir / "good.bvh").string() + " -o " +
                                    (dir / "j.csv").string() + " --metres-per-unit 0.01",
                                &out),
            0)
      << out;
  const JointTrack track = read_joint_track(dir / "j.csv");
  EXPECT_EQ(track.joints, (std::vector<std::string>{"Hips", "Spine", "Spine_End"}));
  ASSERT_EQ(track.frames.size(), 2u);
  EXPECT_NEAR(track.positions[0][2].y(), 1.65, 1e-9);
  EXPECT_NEAR(track.positions[1][0].x(), 0.01, 1e-9);
}

TEST(MotionCli, BadFilesFailWithFileLineAndNoOutput) {
  const std::string good = kGood;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {good.substr(0, good.find("End Site")), "bad.bvh:9: unexpected end of the file"},
      {good.substr(0, good.rfind("1 95")), "expected 2 frames"},
      {replaced("0 0 0 0 5", "0 0 0 5"), "bad.bvh:20: frame 1: expected 9 values"},
      {replaced("CHANNELS 3", "CHANNELS 4"), "bad.bvh:10: CHANNELS of 'Spine'"},
      {replaced("1 95", "1 9x5"), "bad.bvh:20: frame 1, value 2: expected a number"},
      {replaced("Yrotation Xrotation\n    End", "Yrotation Qrotation\n    End"), "got 'Qrotation'"},
      {good.substr(0, good.find("MOTION")), "bad.bvh:15: expected MOTION"},
      {replaced("Frames: 2", "Frames: 5"), "expected 5 frames"},
  };
  for (const auto& [text, message] : cases) {
    testing::TempDir dir;
    write(dir / "bad.bvh", text);
    std::string out;
    // Both commands read through read_bvh; retarget is checked on the last case only.
    for (const std::string command : {"motion dump", "motion retarget"}) {
      if (command == "motion retarget" && message != cases.back().second) continue;
      EXPECT_EQ(
          testing::run_simcap(
              command + " " + (dir / "bad.bvh").string() + " -o " + (dir / "out").string(), &out),
          1)
          << command << ": " << message;
      EXPECT_NE(out.find("simcap: error: " + (dir / "bad.bvh").string()), std::string::npos) << out;
      EXPECT_NE(out.find(message), std::string::npos) << out;
      EXPECT_FALSE(std::filesystem::exists(dir / "out")) << message;
    }
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
  }
  testing::TempDir dir;
  std::string out;
  EXPECT_EQ(
      testing::run_simcap("motion dump /nonexistent.bvh -o " + (dir / "o.csv").string(), &out), 1);
  EXPECT_NE(out.find("/nonexistent.bvh"), std::string::npos) << out;
}

TEST(MotionCli, RetargetPrintsTheFiguresAndWritesAReadableBvh) {
  testing::TempDir dir;
  std::string out;
  ASSERT_EQ(testing::run_simcap("motion retarget " + kWalk + " -o " + (dir / "walk.bvh").string() +
                                    " --fps 30 --joints-csv " + (dir / "walk.csv").string(),
                                &out),
            0)
      << out;
  EXPECT_NE(out.find("naming: cmu-asf"), std::string::npos) << out;
  EXPECT_NE(out.find("not mapped (motion lost): lhand, LFingers, LThumb"), std::string::npos)
      << out;
  EXPECT_NE(out.find("target feet (sole points; floor at 0): lowest foot point over 994 frames"),
            std::string::npos)
      << out;
  const BvhClip clip = read_bvh(dir / "walk.bvh");
  EXPECT_EQ(clip.frame_count(), 249);
  EXPECT_NEAR(clip.fps(), 30.0, 1e-6);
  EXPECT_GE(clip.find("l_talocrural"), 0);
  EXPECT_EQ(read_joint_track(dir / "walk.csv").frames.size(), 249u);
}

TEST(MotionCli, GenerateWritesTheRequestedMotion) {
  testing::TempDir dir;
  std::string out;
  ASSERT_EQ(testing::run_simcap("motion generate walk_in_place -o " + (dir / "w.bvh").string() +
                                    " --duration 2 --fps 25 --height 1.6",
                                &out),
            0)
      << out;
  EXPECT_NE(out.find("feet: lowest foot point"), std::string::npos) << out;
  const BvhClip clip = read_bvh(dir / "w.bvh");
  EXPECT_EQ(clip.frame_count(), 51);
  EXPECT_NE(testing::run_simcap("motion generate moonwalk -o " + (dir / "m.bvh").string(), &out),
            0);
  EXPECT_FALSE(std::filesystem::exists(dir / "m.bvh"));
  ASSERT_EQ(testing::run_simcap("motion dump --help", &out), 0);
  EXPECT_NE(out.find("Examples:"), std::string::npos) << out;
}

TEST(LoadMotion, RetargetsAndResamplesBvhOrGeneratesAtTheRate) {
  const Skeleton s = build_humanoid();
  MotionSource source;
  source.bvh = kWalk;
  const Motion walk = load_motion(source, s, 30.0);
  EXPECT_EQ(walk.frames.size(), 249u);
  EXPECT_DOUBLE_EQ(walk.fps, 30.0);
  // Interpolating between frames whose feet are on the floor keeps them there (the clip's
  // 0.0083333 s frames are not exactly a quarter of 30 fps frames).
  EXPECT_GT(measure_feet(humanoid_feet(s, walk)).lowest_min, -1e-4);

  MotionSource procedural;
  procedural.procedural.kind = "stand";
  procedural.procedural.duration_s = 2.0;
  EXPECT_EQ(load_motion(procedural, s, 50.0).frames.size(), 101u);

  testing::TempDir dir;
  write(dir / "bad.bvh", replaced("Frames: 2", "Frames: 3"));
  source.bvh = dir / "bad.bvh";
  try {
    load_motion(source, s, 30.0);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.bvh:20: expected 3 frames"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace simcap
