// `simcap render` under faults: killed with SIGKILL at random moments, the dataset folder holds
// only whole files (each equal to an uninterrupted render's) and --resume then ends with the
// same bytes; a file-size limit (ulimit -f, a full disk as the writer sees it) ends in a clear
// error that names the file, leaves no temporary file, and keeps the files written before.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <random>

#include "core/atomic_file.h"
#include "tests/support/file_tree.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using testing::read_tree;
using testing::run_simcap;
using testing::shell_words;
using testing::TempDir;

constexpr int kKillPoints = 20;

std::vector<std::string> render_args(const fs::path& out) {
  return {"render",
          std::string(SIMCAP_SOURCE_DIR) + "/scenes/studio4.yaml",
          "-o",
          out.string(),
          "--frames",
          "3",
          "-q",
          "--set",
          "rig.resolution=[96,72]",
          "--set",
          "noise.rgb_sigma=2"};
}

bool is_temporary(const std::string& name) {
  return name.find(".tmp") != std::string::npos;
}

// meta.json without its timings, the one part that may differ between runs (README).
std::string without_timings(const std::string& meta) {
  nlohmann::json j = nlohmann::json::parse(meta);
  j.erase("timings");
  return j.dump();
}

TEST(RenderCrashSafety, KilledAtRandomMomentsThenResumedGivesTheSameBytes) {
  TempDir dir;
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_simcap(shell_words(render_args(dir / "ref"))), 0);
  const auto duration = std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::steady_clock::now() - start);
  const auto ref = read_tree(dir / "ref");
  std::mt19937 rng(20);
  std::uniform_int_distribution<long> moment(0, duration.count());
  int killed = 0;
  for (int k = 0; k < kKillPoints; ++k) {
    const fs::path out = dir / ("run" + std::to_string(k));
    killed += testing::run_simcap_killed(render_args(out), std::chrono::microseconds(moment(rng)));
    if (fs::exists(out)) {
      // What a reader finds after the kill: whole files or temporaries, never a half file.
      for (const auto& [name, content] : read_tree(out)) {
        if (is_temporary(name)) continue;
        ASSERT_TRUE(ref.count(name)) << name;
        if (name == "meta.json") {
          // Rewritten as frames complete ("complete": false until the end); whole, so it parses.
          EXPECT_TRUE(nlohmann::json::accept(content)) << "after kill " << k;
        } else {
          EXPECT_TRUE(content == ref.at(name)) << name << " after kill " << k;
        }
      }
    }
    std::vector<std::string> resume = render_args(out);
    resume.push_back("--resume");
    ASSERT_EQ(run_simcap(shell_words(resume)), 0) << k;
    const auto resumed = read_tree(out);
    ASSERT_EQ(resumed.size(), ref.size()) << "kill " << k;
    for (const auto& [name, content] : resumed) {
      ASSERT_TRUE(ref.count(name)) << name << " after kill " << k;
      if (name == "meta.json") {
        EXPECT_EQ(without_timings(content), without_timings(ref.at(name)));
      } else {
        EXPECT_TRUE(content == ref.at(name)) << name << " after kill " << k;
      }
    }
    fs::remove_all(out);
  }
  // Kill moments after a run ended test nothing; how many fall inside depends on the load.
  EXPECT_GT(killed, 0);
}

// Killed before scene.yaml: an empty camera folder, a temporary and meta.json saying "complete":
// false. --resume renders it afresh; a folder with a file of someone else's stays refused.
TEST(RenderCrashSafety, ResumeStartsAfreshWhatAKillBeforeTheSceneFileLeft) {
  TempDir dir;
  ASSERT_EQ(run_simcap(shell_words(render_args(dir / "ref"))), 0);
  const fs::path out = dir / "run";
  fs::create_directories(out / "cam00");
  nlohmann::json meta = nlohmann::json::parse(read_tree(dir / "ref").at("meta.json"));
  meta["complete"] = false;
  write_text_atomic(out / "meta.json", meta.dump(2));
  write_text_atomic(out / ".scene.tmp123_0.yaml", "scene:");
  std::vector<std::string> resume = render_args(out);
  resume.push_back("--resume");
  ASSERT_EQ(run_simcap(shell_words(resume)), 0);
  const auto ref = read_tree(dir / "ref");
  const auto resumed = read_tree(out);
  ASSERT_EQ(resumed.size(), ref.size());
  for (const auto& [name, content] : resumed) {
    ASSERT_TRUE(ref.count(name)) << name;
    if (name != "meta.json") {
      EXPECT_TRUE(content == ref.at(name)) << name;
    }
  }

  const fs::path other = dir / "other";
  fs::create_directories(other);
  write_text_atomic(other / "meta.json", meta.dump(2));
  write_text_atomic(other / "notes.txt", "mine");
  std::vector<std::string> refused = render_args(other);
  refused.push_back("--resume");
  std::string said;
  EXPECT_EQ(run_simcap(shell_words(refused), &said), 1);
  EXPECT_NE(said.find("--resume: the folder holds no simcap dataset"), std::string::npos) << said;
  EXPECT_TRUE(fs::exists(other / "notes.txt"));
}

TEST(RenderCrashSafety, AFullDiskEndsInAClearErrorWithoutHalfFiles) {
  TempDir dir;
  ASSERT_EQ(run_simcap(shell_words(render_args(dir / "ref"))), 0);
  const auto ref = read_tree(dir / "ref");
  // No file may grow beyond 8 KiB: the colour images are larger.
  std::string log;
  const int status =
      testing::run_simcap_file_limited(shell_words(render_args(dir / "out")), 8192, &log);
  EXPECT_EQ(status, 1) << log;
  EXPECT_NE(log.find(dir.path().string()), std::string::npos) << log;
  for (const auto& [name, content] : read_tree(dir / "out")) {
    EXPECT_FALSE(is_temporary(name)) << name;
    ASSERT_TRUE(ref.count(name)) << name;
    if (name != "meta.json") {
      EXPECT_TRUE(content == ref.at(name)) << name;
    }
  }
}

}  // namespace
}  // namespace simcap
