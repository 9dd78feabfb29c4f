#include <gtest/gtest.h>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/joint_track.h"
#include "tests/support/temp_dir.h"
#include "tests/tracker/capsule_dataset.h"
#include "tracker/common/track_folder.h"
#include "tracker/registry.h"

namespace simcap::tracker {
namespace {

namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

TEST(Registry, EveryMethodHasOneFamily) {
  for (const auto& [name, method] : kTrackMethods) {
    if (method == TrackMethod::automatic) continue;
    int families = 0;
    for (const TrackerFamily& f : tracker_families()) families += f.method == method ? 1 : 0;
    EXPECT_EQ(families, 1) << name;
    EXPECT_FALSE(tracker_family(method).summary.empty()) << name;
  }
  EXPECT_EQ(tracker_families().size(), kTrackMethods.size() - 1);
}

TEST(Registry, AutomaticPicksTheFamilyForTheCameras) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "one", {.frames = 1, .cameras = 1});
  testing::write_capsule_dataset(dir / "two", {.frames = 1, .cameras = 2});
  EXPECT_EQ(resolve_method(TrackMethod::automatic, Dataset(dir / "one")), TrackMethod::monocular);
  EXPECT_EQ(resolve_method(TrackMethod::automatic, Dataset(dir / "two")), TrackMethod::moschini);
  EXPECT_EQ(resolve_method(TrackMethod::sik, Dataset(dir / "one")), TrackMethod::sik);
}

TEST(Registry, RefusesADatasetTheMethodCannotUseBeforeWritingAnything) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "one", {.frames = 2, .cameras = 1});
  std::string log;
  EXPECT_EQ(run_simcap("track " + (dir / "one").string() + " -o " + (dir / "t").string() +
                           " --method moschini",
                       &log),
            1);
  EXPECT_NE(log.find("1 camera, needs at least 2 for --method moschini"), std::string::npos) << log;
  EXPECT_NE(log.find("use --method sik, --method monocular instead"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "t"));

  // What the check reads, directly: cameras, colour images, ground truth.
  const Dataset one(dir / "one");
  EXPECT_EQ(missing_for({.min_cameras = 2}, one), "1 camera, needs at least 2");
  EXPECT_EQ(missing_for({.depth = true}, one), "no cam00/depth images");
  EXPECT_EQ(missing_for({.colour = true, .ground_truth = true}, one), "");
  fs::remove(dir / "one" / "gt" / "joints3d.csv");
  EXPECT_EQ(missing_for({.ground_truth = true}, one), "no gt/joints3d.csv");
}

// --effectors and --detections choose sik's and triangulate's input: with another method (or the
// default, which picks moschini or monocular) they would be ignored without a word.
TEST(Registry, RefusesAnotherMethodsOption) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "ds", {.frames = 2, .cameras = 2});
  const std::string track = "track " + (dir / "ds").string() + " -o " + (dir / "t").string();
  std::string log;
  EXPECT_EQ(run_simcap(track + " --effectors depth", &log), 1);
  EXPECT_NE(log.find("--effectors: only --method sik reads it, and the method is auto (moschini "
                     "for the dataset's 2 cameras); add --method sik, or leave --effectors out"),
            std::string::npos)
      << log;
  // Each method's own options: monocular's particles, moschini's voxels, sik's and monocular's
  // seed (loop's --seed is the render's, which every method reads).
  EXPECT_EQ(run_simcap(track + " --particles 50", &log), 1);
  EXPECT_NE(log.find("--particles: only --method monocular reads it"), std::string::npos) << log;
  EXPECT_EQ(run_simcap(track + " --method sik --voxel 0.03", &log), 1);
  EXPECT_NE(log.find("--voxel: only --method moschini reads it, and the method is sik;"),
            std::string::npos)
      << log;
  EXPECT_EQ(run_simcap(track + " --method moschini --seed 2", &log), 1);
  EXPECT_NE(log.find("--seed: only --method sik or monocular reads it"), std::string::npos) << log;
  EXPECT_EQ(run_simcap(track + " --method sik --detections det.json", &log), 1);
  EXPECT_NE(log.find("--detections: only --method triangulate reads it, and the method is sik;"),
            std::string::npos)
      << log;
  EXPECT_EQ(run_simcap("loop " + std::string(SIMCAP_SOURCE_DIR) +
                           "/scenes/studio4.yaml -o never --method moschini --effectors mono",
                       &log),
            1);
  EXPECT_NE(log.find("--effectors: only --method sik reads it, and the method is moschini;"),
            std::string::npos)
      << log;
  EXPECT_EQ(run_simcap("loop " + std::string(SIMCAP_SOURCE_DIR) +
                           "/scenes/studio4.yaml -o never --method sik --particles 50",
                       &log),
            1);
  EXPECT_NE(log.find("--particles: only --method monocular reads it, and the method is sik;"),
            std::string::npos)
      << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
  EXPECT_EQ(run_simcap(track + " --method sik --effectors gt -q", &log), 0) << log;
  EXPECT_EQ(run_simcap(track + " --voxel 0.03 -q", &log), 0) << log;
}

// An interrupted render holds its first frames only: tracking them would pass for the whole.
TEST(Registry, RefusesADatasetWhoseRenderDidNotFinish) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "ds", {.frames = 2, .cameras = 2});
  write_text_atomic(dir / "ds" / "meta.json",
                    "{\"simcap_version\": \"0.1.0\", \"complete\": false}\n");
  std::string log;
  EXPECT_EQ(run_simcap("track " + (dir / "ds").string() + " -o " + (dir / "t").string() +
                           " --init auto --silhouettes bgsub",
                       &log),
            1);
  EXPECT_NE(log.find("meta.json: \"complete\": false: the render of this dataset did not finish"),
            std::string::npos)
      << log;
  EXPECT_NE(log.find("--resume"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
  write_text_atomic(dir / "ds" / "meta.json",
                    "{\"simcap_version\": \"0.1.0\", \"complete\": true}\n");
  EXPECT_NO_THROW(Dataset(dir / "ds"));
}

TEST(Registry, ALoopsOutputFolderNamesItsDataset) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "loop" / "dataset", {.frames = 2, .cameras = 2});
  std::string log;
  EXPECT_EQ(run_simcap("track " + (dir / "loop").string() + " -o " + (dir / "t").string(), &log),
            1);
  EXPECT_NE(log.find("the output folder of simcap loop or demo, not a dataset; its dataset is " +
                     (dir / "loop" / "dataset").string()),
            std::string::npos)
      << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
  EXPECT_NO_THROW(Dataset(dir / "loop" / "dataset"));
}

TEST(TrackFolder, ReplacesTheTrackOnlyWhenCommitted) {
  TempDir dir;
  const fs::path track = dir / "track";
  write_text_atomic(track / "joints3d.csv", "old\n");
  {
    TrackFolder failed(track);
    write_text_atomic(failed.path() / "joints3d.csv", "half\n");
  }
  EXPECT_EQ(read_text(track / "joints3d.csv"), "old\n");
  EXPECT_FALSE(fs::exists(dir / "track.partial"));
  {
    TrackFolder run(track);
    write_text_atomic(run.path() / "joints3d.csv", "new\n");
    run.commit();
  }
  EXPECT_EQ(read_text(track / "joints3d.csv"), "new\n");
  EXPECT_FALSE(fs::exists(dir / "track.partial"));
  EXPECT_FALSE(fs::exists(dir / "track.old"));
}

TEST(TrackFolder, RefusesAFolderThatIsNotATrack) {
  TempDir dir;
  write_text_atomic(dir / "mine" / "notes.txt", "keep me\n");
  EXPECT_THROW(TrackFolder(dir / "mine"), Error);
  EXPECT_EQ(read_text(dir / "mine" / "notes.txt"), "keep me\n");
  fs::create_directories(dir / "empty");
  EXPECT_NO_THROW(TrackFolder(dir / "empty"));
}

// --frames reaches every family: each tracks the first N frames and writes those only.
TEST(Registry, EveryFamilyTracksTheFirstFramesOnly) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "ds", {.frames = 4, .cameras = 2});
  for (const char* method : {"moschini", "sik", "monocular"}) {
    const fs::path out = dir / method;
    std::string log;
    ASSERT_EQ(run_simcap("track " + (dir / "ds").string() + " -o " + out.string() + " --method " +
                             method + " --frames 2 --quiet",
                         &log),
              0)
        << method << ": " << log;
    EXPECT_EQ(read_joint_track(out / "joints3d.csv").frames, (std::vector<int>{0, 1})) << method;
  }
  std::string log;
  EXPECT_NE(
      run_simcap("track " + (dir / "ds").string() + " -o " + (dir / "t").string() + " --frames 0",
                 &log),
      0);
  EXPECT_NE(log.find("--frames"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
}

// A run that fails after it started writing leaves no track folder behind.
TEST(TrackFolder, AFailedTrackLeavesNothing) {
  TempDir dir;
  testing::write_capsule_dataset(dir / "ds", {.frames = 2, .cameras = 4});
  std::string log;
  EXPECT_EQ(run_simcap("track " + (dir / "ds").string() + " -o " + (dir / "t").string() +
                           " --inspect 7 --quiet",
                       &log),
            1);
  EXPECT_NE(log.find("--inspect: frame 7 is not in"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
  EXPECT_FALSE(fs::exists(dir / "t.partial"));
}

}  // namespace
}  // namespace simcap::tracker
