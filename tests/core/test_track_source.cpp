// A track's record of its dataset: the fingerprint follows scene.yaml and the calibration, and
// a track of another dataset is refused with the file that says so.
#include "core/track_source.h"

#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

void write_dataset(const fs::path& d, const std::string& scene, const std::string& calibration) {
  write_text_atomic(d / "scene.yaml", scene);
  write_text_atomic(d / "calibration" / "opencv.yaml", calibration);
}

std::string error_of(const fs::path& dataset, const fs::path& track) {
  try {
    check_track_source(dataset, track);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

TEST(TrackSource, TheFingerprintFollowsTheSceneAndTheCalibration) {
  TempDir dir;
  write_dataset(dir / "a", "rig: 4\n", "K: 1\n");
  write_dataset(dir / "copy", "rig: 4\n", "K: 1\n");
  write_dataset(dir / "calibrated", "rig: 4\n", "K: 2\n");
  write_dataset(dir / "moved", "rig: 4\nK: 1\n", "");
  const std::string a = dataset_fingerprint(dir / "a");
  EXPECT_EQ(a.size(), 16u);
  EXPECT_EQ(a, dataset_fingerprint(dir / "copy"));
  EXPECT_NE(a, dataset_fingerprint(dir / "calibrated"));
  EXPECT_NE(a, dataset_fingerprint(dir / "moved"));
  EXPECT_NE(a, dataset_fingerprint(dir / "empty"));
}

TEST(TrackSource, ATrackOfAnotherDatasetIsRefused) {
  TempDir dir;
  write_dataset(dir / "a", "rig: 4\n", "K: 1\n");
  write_dataset(dir / "b", "rig: 3\n", "K: 1\n");
  write_text_atomic(dir / "track" / kTrackDatasetFile, dataset_fingerprint(dir / "a") + "\n");
  EXPECT_EQ(error_of(dir / "a", dir / "track"), "");
  const std::string other = error_of(dir / "b", dir / "track");
  EXPECT_NE(other.find("dataset.txt:1: the track was made from another dataset"), std::string::npos)
      << other;
  // Tracks without the record (older ones, other tools') are not checked.
  EXPECT_EQ(error_of(dir / "b", dir / "untracked"), "");
  write_text_atomic(dir / "track" / kTrackDatasetFile, "studio4\n");
  EXPECT_NE(error_of(dir / "a", dir / "track").find("'studio4'; expected the 16 hex digits"),
            std::string::npos);
}

}  // namespace
}  // namespace simcap
