// `simcap validate` under faults: killed with SIGKILL at random moments, the report folder holds
// only whole files (each equal to an uninterrupted run's) and a re-run gives the same bytes; a
// file-size limit (ulimit -f, a full disk as the writer sees it) ends in a clear error that
// names the file.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "tests/support/file_tree.h"
#include "tests/support/temp_dir.h"
#include "tests/validate/synthetic_dataset.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::read_tree;
using testing::run_simcap;
using testing::shell_words;
using testing::TempDir;

constexpr int kKillPoints = 20;

std::vector<std::string> validate_args(const fs::path& dir, const fs::path& out) {
  return {"validate", (dir / "data").string(), (dir / "track").string(), "-o", out.string(), "-q"};
}

void write_inputs(const fs::path& dir) {
  const auto d = testing::write_synthetic_dataset(dir / "data");
  testing::write_track(dir / "track", d.truth,
                       [](int frame, const std::string&, const Eigen::Vector3d& p) {
                         return Eigen::Vector3d(p + Eigen::Vector3d(0.01 * (frame % 3), 0.02, 0));
                       });
}

TEST(ReportCrashSafety, KilledAtRandomMomentsLeavesWholeFilesAndAReRunMatches) {
  TempDir dir;
  write_inputs(dir.path());
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_simcap(shell_words(validate_args(dir.path(), dir / "ref"))), 0);
  const auto duration = std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::steady_clock::now() - start);
  const auto ref = read_tree(dir / "ref");
  std::mt19937 rng(20);
  std::uniform_int_distribution<long> moment(0, duration.count());
  int killed = 0;
  for (int k = 0; k < kKillPoints; ++k) {
    const fs::path out = dir / ("r" + std::to_string(k));
    killed += testing::run_simcap_killed(validate_args(dir.path(), out),
                                         std::chrono::microseconds(moment(rng)));
    if (fs::exists(out)) {
      for (const auto& [name, content] : read_tree(out)) {
        if (name.find(".tmp") != std::string::npos) continue;
        ASSERT_TRUE(ref.count(name)) << name;
        EXPECT_TRUE(content == ref.at(name)) << name << " after kill " << k;
      }
    }
    ASSERT_EQ(run_simcap(shell_words(validate_args(dir.path(), out))), 0) << k;
    const auto again = read_tree(out);
    EXPECT_EQ(again.size(), ref.size()) << "kill " << k;
    for (const auto& [name, content] : again) {
      EXPECT_TRUE(ref.count(name) && content == ref.at(name)) << name << " after kill " << k;
    }
  }
  // Kill moments after a run ended test nothing; how many fall inside depends on the load.
  EXPECT_GT(killed, 0);
}

TEST(ReportCrashSafety, AFullDiskEndsInAClearError) {
  TempDir dir;
  write_inputs(dir.path());
  std::string log;
  EXPECT_EQ(testing::run_simcap_file_limited(shell_words(validate_args(dir.path(), dir / "r")),
                                             4096, &log),
            1)
      << log;
  EXPECT_NE(log.find("write failed"), std::string::npos) << log;
  for (const auto& [name, content] : read_tree(dir / "r")) {
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
  }
}

}  // namespace
}  // namespace simcap
