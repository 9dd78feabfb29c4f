// score_effector_tracks on a synthetic dataset: tracks made from gt/joints2d.csv with known pixel
// offsets and lost frames, split by the joint's visibility; pixel_errors on a known list; and
// the errors for a bad effectors2d.csv.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/csv.h"
#include "core/effector_track.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"
#include "tests/validate/synthetic_dataset.h"
#include "validate/effector_scores.h"
#include "validate/validate_job.h"
#include "validate/visibility.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::TempDir;

// TRACK/effectors2d.csv from the truth's pixels of l_elbow (+3, +4: 5 px) and r_radiocarpal
// (+6, +8: 10 px) in cam00 and cam01; r_radiocarpal is `lost` at frame 0 and has no row at 1.
void write_effectors(const fs::path& data, const fs::path& track) {
  fs::create_directories(track);
  const std::map<std::string, std::pair<double, double>> offset = {{"l_elbow", {3, 4}},
                                                                   {"r_radiocarpal", {6, 8}}};
  CsvReader in(data / "gt" / "joints2d.csv", kJoints2dColumns);
  CsvWriter out(track / "effectors2d.csv", kEffectors2dColumns);
  while (in.next()) {
    const std::string& cam = in.text(1);
    const auto o = offset.find(in.text(2));
    if (o == offset.end() || (cam != "cam00" && cam != "cam01")) continue;
    const long frame = in.integer(0);
    const bool wrist = o->first == "r_radiocarpal";
    if (wrist && frame == 1) continue;
    out.out() << frame << ',' << cam << ',' << (wrist ? "r_hand" : "elbow") << ',' << o->first
              << ',' << in.number(3) + o->second.first << ',' << in.number(4) + o->second.second
              << ",0,0," << (wrist && frame == 0 ? "lost" : "tracking") << '\n';
  }
  out.commit();
}

TEST(EffectorScores, PixelErrorsOfAKnownList) {
  const PixelErrors p = pixel_errors({4, 1, 3, 2});
  EXPECT_EQ(p.count, 4);
  EXPECT_DOUBLE_EQ(p.median_px, 2.5);
  EXPECT_DOUBLE_EQ(p.mean_px, 2.5);
  EXPECT_DOUBLE_EQ(p.p90_px, 4.0);
  EXPECT_DOUBLE_EQ(p.max_px, 4.0);
  EXPECT_EQ(pixel_errors({}).count, 0);
}

TEST(EffectorScores, KnownOffsetsLostFramesAndSelfOcclusion) {
  TempDir dir;
  const auto d = testing::write_synthetic_dataset(dir / "data", 10);
  write_effectors(dir / "data", dir / "track");
  const auto s = score_effector_tracks(dir / "data", dir / "track", d.truth.frames,
                                       {"cam00", "cam01", "cam02"});
  ASSERT_TRUE(s.has_value());
  ASSERT_EQ(s->per_effector.size(), 4u);
  for (const auto& e : s->per_effector) {
    const bool wrist = e.joint == "r_radiocarpal";
    EXPECT_EQ(e.frames, 10);
    EXPECT_EQ(e.lost, wrist ? 2 : 0) << e.camera << ' ' << e.joint;
    EXPECT_NEAR(e.all.median_px, wrist ? 10.0 : 5.0, 1e-3);
    EXPECT_NEAR(e.all.max_px, wrist ? 10.0 : 5.0, 1e-3);
    // The synthetic dataset labels l_elbow self_occluded in cam01, everything else visible.
    const bool occluded = e.joint == "l_elbow" && e.camera == "cam01";
    EXPECT_EQ(e.self_occluded.count, occluded ? 10 : 0);
    EXPECT_EQ(e.visible.count, occluded ? 0 : e.all.count);
  }
  EXPECT_EQ(s->frames, 40);
  EXPECT_EQ(s->lost, 4);
  EXPECT_DOUBLE_EQ(s->lost_fraction, 0.1);
  EXPECT_NEAR(s->self_occluded.median_px, 5.0, 1e-3);
  EXPECT_EQ(s->all.count, 36);
}

TEST(EffectorScores, ValidateWritesThemIntoMetricsJson) {
  TempDir dir;
  const auto d = testing::write_synthetic_dataset(dir / "data", 10);
  testing::write_track(dir / "track", d.truth,
                       [](int, const std::string&, const Eigen::Vector3d& p) { return p; });
  ValidateOptions o;
  o.quiet = true;
  o.media = false;
  EXPECT_FALSE(validate_dataset(dir / "data", dir / "track", dir / "r0", o).effectors);
  std::ifstream none(dir / "r0" / "metrics.json");
  EXPECT_TRUE(nlohmann::json::parse(none)["effectors2d"].is_null());

  write_effectors(dir / "data", dir / "track");
  const ValidateSummary s = validate_dataset(dir / "data", dir / "track", dir / "r1", o);
  ASSERT_TRUE(s.effectors);
  std::ifstream in(dir / "r1" / "metrics.json");
  const auto j = nlohmann::json::parse(in)["effectors2d"];
  EXPECT_EQ(j["lost"], 4);
  EXPECT_EQ(j["per_effector"].size(), 4u);
  EXPECT_NEAR(j["self_occluded"]["median_px"].get<double>(), 5.0, 1e-3);
}

TEST(EffectorScores, BadTablesAreNamed) {
  TempDir dir;
  const auto d = testing::write_synthetic_dataset(dir / "data", 4);
  const fs::path track = dir / "track";
  fs::create_directories(track);
  auto score = [&](const std::string& row) {
    std::ofstream(track / "effectors2d.csv")
        << "frame,camera,effector,joint,u,v,part_u,part_v,state\n"
        << row << '\n';
    return error_of([&] {
      score_effector_tracks(dir / "data", track, d.truth.frames, {"cam00", "cam01", "cam02"});
    });
  };
  EXPECT_NE(score("0,cam09,head,skullbase,1,2,1,2,tracking").find("unknown camera 'cam09'"),
            std::string::npos);
  EXPECT_NE(score("0,cam00,head,skullbase,1,2,1,2,flying").find("unknown state 'flying'"),
            std::string::npos);
  EXPECT_NE(score("99,cam00,head,skullbase,1,2,1,2,tracking").find("frame 99"), std::string::npos);
  EXPECT_NE(score("0,cam00,head,no_such_joint,1,2,1,2,tracking").find("no_such_joint"),
            std::string::npos);
}

}  // namespace
}  // namespace simcap
