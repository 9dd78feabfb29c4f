// Collection specs: what they expand to, and the file:line errors of bad ones.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <set>

#include "collect/collection_spec.h"
#include "core/atomic_file.h"
#include "scenes/scene.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::error_of;
using testing::TempDir;
namespace fs = std::filesystem;

const std::string kScene = std::string(SIMCAP_SOURCE_DIR) + "/scenes/studio4.yaml";
const std::string kAssets = SIMCAP_MOCAP_DIR;

fs::path write_spec(const TempDir& dir, const std::string& text) {
  const fs::path p = dir / "spec.yaml";
  std::ofstream(p) << text;
  return p;
}

std::string valid_spec() {
  return "count: 12\n"
         "seed: 3\n"
         "frames: 2\n"
         "scenes: [" +
         kScene +
         "]\n"
         "set: {rig.resolution: [64, 48]}\n"
         "motions:\n"
         "  - folder: " +
         kAssets +
         "\n"
         "  - {procedural: walk_path, speed: {uniform: [0.8, 1.6]}}\n"
         "bodies:\n"
         "  height: {uniform: [1.55, 1.95]}\n"
         "  girth: [0.9, 1.1]\n"
         "vary:\n"
         "  render.first_frame: {uniform: [0, 10]}\n";
}

std::string value(const CollectionSequence& s, const std::string& key) {
  for (const auto& [k, v] : s.parameters) {
    if (k == key) return v;
  }
  return "<none>";
}

TEST(CollectionSpec, CrossesListsAndDrawsRangesPerSequence) {
  TempDir dir;
  const CollectionSpec spec = load_collection(write_spec(dir, valid_spec()));
  ASSERT_EQ(spec.count, 12);
  ASSERT_EQ(spec.motions.size(), 3u);  // two clips of the folder and the procedural walk
  // Motions x girth = 6 combinations, each twice in 12 sequences, the girth fastest.
  std::set<std::string> combos;
  for (int id = 0; id < 12; ++id) {
    const CollectionSequence s = collection_sequence(spec, id);
    EXPECT_EQ(value(s, "actors[0].girth"), id % 2 ? "1.1" : "0.9");
    combos.insert(s.motion + "/" + value(s, "actors[0].girth"));
    const double h = std::stod(value(s, "actors[0].height"));
    EXPECT_GE(h, 1.55);
    EXPECT_LE(h, 1.95);
    const std::string first = value(s, "render.first_frame");
    EXPECT_EQ(first.find('.'), std::string::npos) << "integer ends draw integers: " << first;
    EXPECT_EQ(s.overrides.front(), "rig.resolution=[64, 48]");
  }
  EXPECT_EQ(combos.size(), 6u);
  EXPECT_EQ(value(collection_sequence(spec, 4), "motion"), "walk_path");
  EXPECT_NE(value(collection_sequence(spec, 4), "motion.speed"), "<none>");
}

TEST(CollectionSpec, SequencesDependOnTheMasterSeedAndIdOnly) {
  TempDir dir;
  const CollectionSpec spec = load_collection(write_spec(dir, valid_spec()));
  const CollectionSequence a = collection_sequence(spec, 7);
  const CollectionSequence b = collection_sequence(spec, 7);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.overrides, b.overrides);
  std::set<std::uint64_t> seeds;
  std::set<std::string> heights;
  for (int id = 0; id < 12; ++id) {
    seeds.insert(collection_sequence(spec, id).seed);
    heights.insert(value(collection_sequence(spec, id), "actors[0].height"));
  }
  EXPECT_EQ(seeds.size(), 12u);
  EXPECT_GT(heights.size(), 8u);
  std::string other = valid_spec();
  other.replace(other.find("seed: 3"), 7, "seed: 4");
  TempDir dir2;
  EXPECT_NE(collection_sequence(load_collection(write_spec(dir2, other)), 7).seed, a.seed);
}

TEST(CollectionSpec, CountDefaultsToTheCombinations) {
  TempDir dir;
  std::string text = valid_spec();
  text.erase(0, text.find('\n') + 1);
  EXPECT_EQ(load_collection(write_spec(dir, text)).count, 6);
}

// The spec with `from` replaced by `to`, loaded: its error message.
std::string error_with(const std::string& from, const std::string& to) {
  TempDir dir;
  std::string text = valid_spec();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const fs::path p = write_spec(dir, text);
  return error_of([&] { load_collection(p); });
}

TEST(CollectionSpec, CameraJitterIsAnAxisSeededPerSequence) {
  TempDir dir;
  const fs::path p = write_spec(dir, valid_spec() +
                                         "camera_jitter:\n"
                                         "  position_m: {uniform: [0, 0.05]}\n"
                                         "  rotation_deg: [1, 3]\n");
  const CollectionSpec spec = load_collection(p);
  EXPECT_EQ(spec.count, 12);
  std::set<std::string> seeds, turns;
  for (int id = 0; id < 4; ++id) {
    const CollectionSequence s = collection_sequence(spec, id);
    const double shift = std::stod(value(s, "rig.jitter.position_m"));
    EXPECT_GE(shift, 0);
    EXPECT_LE(shift, 0.05);
    turns.insert(value(s, "rig.jitter.rotation_deg"));
    const std::string seed = "rig.jitter.seed=" + std::to_string(s.seed);
    EXPECT_EQ(std::count(s.overrides.begin(), s.overrides.end(), seed), 1) << id;
    seeds.insert(seed);
    // The scene takes the overrides: its cameras are those of the unjittered rig, moved.
    const Scene scene = load_scene(s.scene, s.overrides);
    std::vector<std::string> still = s.overrides;
    std::erase_if(still, [](const std::string& o) { return o.rfind("rig.jitter", 0) == 0; });
    const Scene base = load_scene(s.scene, still);
    const double moved =
        (scene.cameras[0].centre() - base.cameras[0].centre()).cwiseAbs().maxCoeff();
    EXPECT_LE(moved, shift + 1e-12);
    EXPECT_GT((scene.cameras[0].R - base.cameras[0].R).norm(), 0);
  }
  EXPECT_EQ(turns, (std::set<std::string>{"1", "3"}));  // a crossed list
  EXPECT_EQ(seeds.size(), 4u);
}

// Split the fuzz corpus's ASF + AMC pair ("==> name <==" sections) into a folder.
void write_asf_amc(const fs::path& folder, const std::vector<std::string>& amcs,
                   const std::vector<std::string>& asfs) {
  const std::string text =
      read_text(fs::path(SIMCAP_SOURCE_DIR) / "tests/fuzz/corpus/asf_amc/cmu_like_3frames.txt");
  const size_t amc_at = text.find("==> clip.amc <==");
  ASSERT_NE(amc_at, std::string::npos);
  const size_t asf_body = text.find('\n') + 1, amc_body = text.find('\n', amc_at) + 1;
  fs::create_directories(folder);
  for (const auto& a : asfs)
    write_text_atomic(folder / a, text.substr(asf_body, amc_at - asf_body));
  for (const auto& a : amcs) write_text_atomic(folder / a, text.substr(amc_body));
}

TEST(CollectionSpec, MotionFoldersOfAmcClipsFindTheirAsf) {
  TempDir dir;
  write_asf_amc(dir / "cmu", {"07_02.amc", "07_01.amc"}, {"07.asf", "08.asf"});
  std::string text = valid_spec();
  text.replace(text.find(kAssets), kAssets.size(), (dir / "cmu").string());
  const CollectionSpec spec = load_collection(write_spec(dir, text));
  ASSERT_EQ(spec.motions.size(), 3u);
  EXPECT_EQ(spec.motions[0].label, "07_01.amc");
  EXPECT_EQ(spec.motions[1].label, "07_02.amc");
  const auto& fixed = spec.motions[0].fixed;
  ASSERT_EQ(fixed.size(), 2u);
  EXPECT_EQ(fixed[0].first, "amc");
  EXPECT_EQ(fixed[1].first, "asf");
  EXPECT_NE(fixed[1].second.find("07.asf"), std::string::npos) << fixed[1].second;
  const CollectionSequence s = collection_sequence(spec, 0);
  EXPECT_EQ(s.motion, "07_01.amc");
  // A clip of another subject: no skeleton for it among several, unless named.
  write_asf_amc(dir / "cmu", {"09_01.amc"}, {});
  const std::string no_asf = error_of([&] { load_collection(write_spec(dir, text)); });
  EXPECT_NE(no_asf.find("spec.yaml:7: motions[0].folder: no ASF skeleton for 09_01.amc"),
            std::string::npos)
      << no_asf;
  const std::string folder = "folder: " + (dir / "cmu").string();
  text.replace(text.find(folder), folder.size(), "{" + folder + ", asf: cmu/08.asf}");
  const CollectionSpec named = load_collection(write_spec(dir, text));
  ASSERT_EQ(named.motions.size(), 4u);
  EXPECT_EQ(named.motions[2].label, "09_01.amc");
  EXPECT_NE(named.motions[2].fixed[1].second.find("08.asf"), std::string::npos);
}

TEST(CollectionSpec, BadSpecsNameFileLineAndKey) {
  EXPECT_NE(error_with("count: 12", "cuont: 12").find("spec.yaml:1: cuont: unknown key"),
            std::string::npos)
      << error_with("count: 12", "cuont: 12");
  EXPECT_NE(error_with("girth: [0.9, 1.1]", "girth: []").find("spec.yaml:11: bodies.girth"),
            std::string::npos)
      << error_with("girth: [0.9, 1.1]", "girth: []");
  const std::string empty_range = error_with("[1.55, 1.95]", "[1.95, 1.55]");
  EXPECT_NE(empty_range.find("spec.yaml:10: bodies.height: the range [1.95, 1.55] is empty"),
            std::string::npos)
      << empty_range;
  TempDir empty;
  const std::string no_clips = error_with("folder: " + kAssets, "folder: " + empty.path().string());
  EXPECT_NE(no_clips.find("spec.yaml:7: motions[0].folder: the folder"), std::string::npos)
      << no_clips;
  EXPECT_NE(no_clips.find("holds no motion clip"), std::string::npos) << no_clips;
  // A value the scene refuses: at the spec's line, with the scene's own message.
  const std::string bad_height = error_with("[1.55, 1.95]", "[1.55, 3.5]");
  EXPECT_NE(bad_height.find("spec.yaml:10: actors[0].height:"), std::string::npos) << bad_height;
  EXPECT_NE(bad_height.find("expected a number in [0.5, 2.5]"), std::string::npos) << bad_height;
  const std::string bad_key = error_with("render.first_frame", "render.frist_frame");
  EXPECT_NE(bad_key.find("spec.yaml:13: render.frist_frame:"), std::string::npos) << bad_key;
  const std::string bad_motion = error_with("procedural: walk_path", "procedural: fly");
  EXPECT_NE(bad_motion.find("spec.yaml:8: motions:"), std::string::npos) << bad_motion;
  const std::string missing = error_with("frames: 2\n", "");
  EXPECT_NE(missing.find("spec.yaml"), std::string::npos) << missing;
  EXPECT_NE(missing.find("frames"), std::string::npos) << missing;
  const std::string jitter = valid_spec() + "camera_jitter: {positon_m: 0.1}\n";
  TempDir jdir;
  const std::string bad_jitter = error_of([&] { load_collection(write_spec(jdir, jitter)); });
  EXPECT_NE(bad_jitter.find("spec.yaml:14: camera_jitter.positon_m: unknown key"),
            std::string::npos)
      << bad_jitter;
  const std::string empty_jitter = error_of([&] {
    load_collection(
        write_spec(jdir, valid_spec() + "camera_jitter: {rotation_deg: {uniform: [3, 1]}}\n"));
  });
  EXPECT_NE(
      empty_jitter.find("spec.yaml:14: camera_jitter.rotation_deg: the range [3, 1] is empty"),
      std::string::npos)
      << empty_jitter;
  const std::string far_jitter = error_of([&] {
    load_collection(write_spec(jdir, valid_spec() + "camera_jitter: {position_m: [0, 5]}\n"));
  });
  EXPECT_NE(far_jitter.find("spec.yaml:14: rig.jitter.position_m:"), std::string::npos)
      << far_jitter;
  EXPECT_NE(far_jitter.find("could move camera"), std::string::npos) << far_jitter;
  const std::string no_scene = error_with(kScene, "nowhere.yaml");
  EXPECT_NE(no_scene.find("spec.yaml:4: scenes[0]: no such file"), std::string::npos) << no_scene;
}

}  // namespace
}  // namespace simcap
