// `simcap render` under faults: killed with SIGKILL at random moments, the dataset folder holds
// only whole files (each equal to an uninterrupted render's) and --resume then ends with the
// same bytes; a file-size limit (ulimit -f, a full disk as the writer sees it) ends in a clear
// error that names the file, leaves no temporary file, and keeps the files written before.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <random>

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
