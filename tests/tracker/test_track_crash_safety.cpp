// `simcap track` under faults: killed with SIGKILL at random moments, TRACK is either the
// previous track untouched or the new one whole, and a re-run gives the uninterrupted run's
// bytes; a file-size limit (ulimit -f, a full disk as the writer sees it) ends in a clear error
// with the previous track untouched and no staging folder left.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "core/atomic_file.h"
#include "tests/support/file_tree.h"
#include "tests/support/temp_dir.h"
#include "tests/tracker/capsule_dataset.h"

namespace simcap::tracker {
namespace {

namespace fs = std::filesystem;
using testing::read_tree;
using testing::run_simcap;
using testing::shell_words;
using testing::TempDir;

constexpr int kKillPoints = 20;

std::vector<std::string> track_args(const fs::path& dataset, const fs::path& out) {
  return {"track", dataset.string(), "-o", out.string(), "--quiet"};
}

// The track without its wall-clock times (diagnostics/timings.csv), the one part that may differ
// between runs.
std::map<std::string, std::string> track_tree(const fs::path& track) {
  auto tree = read_tree(track);
  tree.erase("diagnostics/timings.csv");
  return tree;
}

// A previous track the runs replace: a joints3d.csv of its own and a marker file.
void write_previous_track(const fs::path& track) {
  write_text_atomic(track / "joints3d.csv", "previous\n");
  write_text_atomic(track / "previous.txt", "marker\n");
}

bool is_previous_track(const fs::path& track) {
  return read_tree(track) == std::map<std::string, std::string>{{"joints3d.csv", "previous\n"},
                                                                {"previous.txt", "marker\n"}};
}

TEST(TrackCrashSafety, KilledAtRandomMomentsTheTrackIsOldOrWholeAndAReRunMatches) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "ds",
                                 {.frames = 3, .cameras = 4, .width = 160, .height = 120});
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(run_simcap(shell_words(track_args(dir / "ds", dir / "ref"))), 0);
  const auto duration = std::chrono::duration_cast<std::chrono::microseconds>(
      std::chrono::steady_clock::now() - start);
  const auto ref = track_tree(dir / "ref");
  ASSERT_TRUE(ref.count("joints3d.csv"));
  std::mt19937 rng(20);
  std::uniform_int_distribution<long> moment(0, duration.count());
  int killed = 0;
  for (int k = 0; k < kKillPoints; ++k) {
    const fs::path out = dir / ("t" + std::to_string(k));
    write_previous_track(out);
    killed += testing::run_simcap_killed(track_args(dir / "ds", out),
                                         std::chrono::microseconds(moment(rng)));
    ASSERT_TRUE(fs::exists(out)) << "kill " << k;
    EXPECT_TRUE(is_previous_track(out) || track_tree(out) == ref) << "kill " << k;
    ASSERT_EQ(run_simcap(shell_words(track_args(dir / "ds", out))), 0) << k;
    EXPECT_EQ(track_tree(out), ref) << "kill " << k;
    EXPECT_FALSE(fs::exists(dir / ("t" + std::to_string(k) + ".partial"))) << k;
    EXPECT_FALSE(fs::exists(dir / ("t" + std::to_string(k) + ".old"))) << k;
  }
  // Kill moments after a run ended test nothing; how many fall inside depends on the load.
  EXPECT_GT(killed, 0);
}

TEST(TrackCrashSafety, AFullDiskEndsInAClearErrorAndKeepsThePreviousTrack) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "ds",
                                 {.frames = 3, .cameras = 4, .width = 160, .height = 120});
  write_previous_track(dir / "t");
  // joints3d.csv holds every joint of every frame: far more than 1 KiB.
  std::string log;
  EXPECT_EQ(
      testing::run_simcap_file_limited(shell_words(track_args(dir / "ds", dir / "t")), 1024, &log),
      1)
      << log;
  EXPECT_NE(log.find("t.partial"), std::string::npos) << log;
  EXPECT_TRUE(is_previous_track(dir / "t"));
  EXPECT_FALSE(fs::exists(dir / "t.partial"));
  EXPECT_FALSE(fs::exists(dir / "t.old"));
}

}  // namespace
}  // namespace simcap::tracker
