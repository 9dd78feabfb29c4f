// Two people crossing (scenes/two_people.yaml, a few frames at low resolution): the dataset is
// read for one actor at a time, `simcap track --actor` follows the one named and records it
// (sik starts on the first actor's own parts),
// validate scores that actor.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include "core/atomic_file.h"
#include "core/csv.h"
#include "core/error.h"
#include "core/joint_track.h"
#include "tests/support/temp_dir.h"
#include "tracker/common/dataset.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

// `frames` frames of the scene from the clip's frame `first` (the scene's frame 0 is 120),
// rendered into `dir`.
fs::path render_two_people(const TempDir& dir, int frames, int first) {
  const fs::path r = dir / "two";
  std::string log;
  const int status =
      run_simcap(std::string("render ") + SIMCAP_SOURCE_DIR + "/scenes/two_people.yaml -o " +
                     r.string() + " -q --frames " + std::to_string(frames) +
                     " --set render.first_frame=" + std::to_string(first),
                 &log);
  EXPECT_EQ(status, 0) << log;
  return r;
}

// Frames 40-53 of the scene: actor1 walks past 0.45 m in front of actor0 (frame 45) and hides
// it from cam00.
const fs::path& crossing() {
  static TempDir dir;
  static const fs::path root = render_two_people(dir, 14, 160);
  return root;
}

// Frames 30-53: actor1 comes from the side, passes 0.45 m in front of actor0 (frame 45) and
// turns away; the track starts before they meet.
const fs::path& approach() {
  static TempDir dir;
  static const fs::path root = render_two_people(dir, 24, 150);
  return root;
}

double mean_error_mm(const JointTrack& truth, const JointTrack& track) {
  double sum = 0;
  int n = 0;
  for (size_t f = 0; f < track.frames.size(); ++f) {
    for (size_t j = 0; j < track.joints.size(); ++j) {
      sum +=
          (track.positions[f][j] - truth.positions[f][truth.joint_index(track.joints[j])]).norm();
      ++n;
    }
  }
  return 1000 * sum / n;
}

TEST(TwoPeople, TheDatasetIsReadForTheChosenActor) {
  const tracker::Dataset first(crossing());
  const tracker::Dataset second(crossing(), "actor1");
  ASSERT_EQ(first.actors(), (std::vector<std::string>{"actor0", "actor1"}));
  EXPECT_EQ(first.actor(), 0);
  EXPECT_EQ(second.actor(), 1);
  // The masks hold each person's own visible pixels, the others' as `others`.
  int own = 0, shared = 0;
  for (int c = 0; c < first.camera_count(); ++c) {
    const cv::Mat a = first.mask(c, 0), b = second.mask(c, 0);
    own += cv::countNonZero(a);
    shared += cv::countNonZero(a & b);
    EXPECT_EQ(cv::countNonZero(first.others(c, 0) != b), 0);
    EXPECT_EQ(cv::countNonZero(second.others(c, 0) != a), 0);
  }
  EXPECT_GT(own, 1000);
  EXPECT_EQ(shared, 0);
  // The ground truth under the actor's own joint names: the "actor1/" rows for actor1.
  const JointTrack all = read_joint_track(first.ground_truth_path());
  const JointTrack mine = second.ground_truth("test");
  ASSERT_GE(mine.joint_index("l_knee"), 0);
  EXPECT_EQ(mine.joint_index("actor1/l_knee"), -1);
  EXPECT_EQ(mine.positions[3][mine.joint_index("l_knee")],
            all.positions[3][all.joint_index("actor1/l_knee")]);
  EXPECT_EQ(first.ground_truth("test").joints.size(), mine.joints.size());
}

TEST(TwoPeople, AnActorTheDatasetLacksIsRefusedListingTheActors) {
  try {
    tracker::Dataset(crossing(), "nobody");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("actor0, actor1"), std::string::npos) << e.what();
  }
  TempDir dir;
  std::string log;
  EXPECT_NE(run_simcap("track " + crossing().string() + " -o " + (dir / "t").string() +
                           " --actor nobody --quiet",
                       &log),
            0);
  EXPECT_NE(log.find("--actor nobody: no such actor; the dataset has actor0, actor1"),
            std::string::npos)
      << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
  // Only moschini follows another actor than the first.
  EXPECT_NE(run_simcap("track " + crossing().string() + " -o " + (dir / "t").string() +
                           " --actor actor1 --method monocular --quiet",
                       &log),
            0);
  EXPECT_NE(log.find("tracks only the first actor"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "t"));
}

TEST(TwoPeople, TheTrackRecordsItsActorAndValidateScoresIt) {
  TempDir dir;
  std::string log;
  ASSERT_EQ(run_simcap("track " + crossing().string() + " -o " + (dir / "t").string() +
                           " --actor actor1 --quiet",
                       &log),
            0)
      << log;
  EXPECT_EQ(read_text(dir / "t" / "actor.txt"), "actor1\n");
  ASSERT_EQ(run_simcap("validate " + crossing().string() + " " + (dir / "t").string() + " -o " +
                           (dir / "v").string() + " --quiet",
                       &log),
            0)
      << log;
  const auto metrics = nlohmann::json::parse(read_text(dir / "v" / "metrics.json"));
  const JointTrack track = read_joint_track(dir / "t" / "joints3d.csv");
  const double own =
      mean_error_mm(tracker::Dataset(crossing(), "actor1").ground_truth("test"), track);
  EXPECT_NEAR(metrics.at("mpjpe_mm").get<double>(), own, 0.01);
  EXPECT_LT(own, 100);  // 75 mm: actor1 is followed, though the crossing costs it
  // It is actor1's track: against actor0 it is metres off.
  EXPECT_GT(mean_error_mm(tracker::Dataset(crossing()).ground_truth("test"), track), 300);
}

// Background subtraction sees both people as one foreground; the person gate (with the volume
// it gives the others, remembered from frame to frame) and the colours learned on the first
// frame (the others' pixels become cover) keep the track on actor0.
TEST(TwoPeople, BackgroundSubtractionKeepsTheTrackOnItsActorThroughTheCrossing) {
  TempDir dir;
  std::string log;
  ASSERT_EQ(run_simcap("track " + approach().string() + " -o " + (dir / "t").string() +
                           " --silhouettes bgsub --quiet",
                       &log),
            0)
      << log;
  const JointTrack track = read_joint_track(dir / "t" / "joints3d.csv");
  const JointTrack own = tracker::Dataset(approach()).ground_truth("test");
  const JointTrack other = tracker::Dataset(approach(), "actor1").ground_truth("test");
  ASSERT_EQ(track.frames.size(), 24u);
  const int root = track.joint_index("humanoid_root");
  ASSERT_GE(root, 0);
  for (size_t f = 0; f < track.frames.size(); ++f) {
    const Eigen::Vector3d& r = track.positions[f][root];
    const double mine = (r - own.positions[f][own.joint_index("humanoid_root")]).norm();
    const double theirs = (r - other.positions[f][other.joint_index("humanoid_root")]).norm();
    // The root stays on actor0 (at most 0.18 m off, while actor1's is 0.5 m away and more);
    // limbs still drift towards actor1 while the two are close (MOSCHINI.md).
    EXPECT_LT(mine, 0.4) << "frame " << track.frames[f];
    EXPECT_LT(mine, theirs) << "frame " << track.frames[f];
  }
  // Once the other person is near, nothing of the track is on actor1.
  EXPECT_GT(mean_error_mm(other, track), 2 * mean_error_mm(own, track));
}

// --init auto with background subtraction: the hull holds both people and the phantom volume
// between them; the named actor's mask points at whom to start on (before, both starts stood
// between the two, 0.6 m from either).
TEST(TwoPeople, AutoStartWithBackgroundSubtractionStartsOnTheNamedActor) {
  for (const std::string actor : {"actor0", "actor1"}) {
    TempDir dir;
    std::string log;
    ASSERT_EQ(run_simcap("track " + approach().string() + " -o " + (dir / "t").string() +
                             " --silhouettes bgsub --init auto --actor " + actor + " --quiet",
                         &log),
              0)
        << log;
    const JointTrack track = read_joint_track(dir / "t" / "joints3d.csv");
    const JointTrack own = tracker::Dataset(approach(), actor).ground_truth("test");
    const JointTrack other =
        tracker::Dataset(approach(), actor == "actor0" ? "actor1" : "actor0").ground_truth("test");
    const Eigen::Vector3d& r = track.positions[0][track.joint_index("humanoid_root")];
    EXPECT_LT((r - own.positions[0][own.joint_index("humanoid_root")]).norm(), 0.2) << actor;
    EXPECT_GT((r - other.positions[0][other.joint_index("humanoid_root")]).norm(), 0.8) << actor;
  }
}

// sik's --init gt starts each camera's parts on the part labels, which name joints and not
// people: only the first actor's own labels may count (the union box of both people's heads
// once put a part between them, where no colour could be learned, and the track crashed).
TEST(TwoPeople, SikStartsEveryPartOnTheFirstActor) {
  TempDir dir;
  std::string log;
  ASSERT_EQ(run_simcap("track " + crossing().string() + " -o " + (dir / "t").string() +
                           " --method sik --effectors multiview --init gt --quiet",
                       &log),
            0)
      << log;
  // The first frame's true joints the actor's own pixels show, per (camera, joint).
  std::map<std::pair<std::string, std::string>, cv::Point2d> seen;
  CsvReader gt(crossing() / "gt" / "joints2d.csv",
               {"frame", "camera", "joint", "u", "v", "depth", "visibility"});
  while (gt.next()) {
    if (gt.integer(0) == 0 && gt.text(6) == "visible") {
      seen[{gt.text(1), gt.text(2)}] = {gt.number(3), gt.number(4)};
    }
  }
  CsvReader track(dir / "t" / "effectors2d.csv",
                  {"frame", "camera", "effector", "joint", "u", "v", "part_u", "part_v", "state"});
  int parts = 0;
  while (track.next()) {
    const auto joint = seen.find({track.text(1), track.text(3)});
    if (track.integer(0) != 0 || track.text(2) == "pelvis" || joint == seen.end()) continue;
    ++parts;
    const std::string where = track.text(1) + " " + track.text(2);
    EXPECT_EQ(track.text(8), "tracking") << where;
    // Hands and feet are tracked from the part's middle, the head from the face: within 25 px
    // of the joint at this size, against 60-90 px to the other person's.
    EXPECT_LT(cv::norm(cv::Point2d(track.number(6), track.number(7)) - joint->second), 25) << where;
  }
  EXPECT_GE(parts, 15);  // of 4 cameras x 5 parts, 3 hidden
}

}  // namespace
}  // namespace simcap
