// --init auto's frames tracked again backwards once the body is measured: frames the forward
// pass left off come back to the pose the last one holds, a frame the forward pass explains
// better keeps its pose, and tracking back goes on from it.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tests/tracker/moschini/track_support.h"
#include "tracker/moschini/track_back.h"

namespace simcap::tracker {
namespace {

// A frame whose output waits, and the step the forward pass took on it.
struct HeldFrame {
  std::shared_ptr<const Observation> obs;
  TrackStep step;
};

// As the job does at the sequence's end: from the last frame back to the first.
void track_back(const BodyDimensions& dims, const BodySurface& surface,
                const TrackerOptions& options, std::vector<HeldFrame>& frames) {
  TrackBack back(dims, surface, options, frames.back().step.pose);
  for (auto it = frames.rbegin(); it != frames.rend(); ++it) back.step(*it->obs, it->step);
}

struct Rig {
  BodyDimensions dims = testing::capsule_body();
  BodySurface surface = testing::capsule_surface();
  StickModel model{dims, JointSet::urdf};
  StickPose truth = testing::walking_pose();
  testing::RigObservation rig = observe(truth);
  std::shared_ptr<const Observation> obs = std::make_shared<Observation>(rig.observation);

  testing::RigObservation observe(const StickPose& pose) const {
    return testing::observe_rig(model, surface, pose, testing::camera_ring(4),
                                Eigen::AlignedBox3d(pose.t0 - Eigen::Vector3d(1.2, 1.05, 1.2),
                                                    pose.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)));
  }
  // Six frames of the same observation, the forward pass's steps `first` and then `last`.
  std::vector<HeldFrame> held(const StickPose& first, const StickPose& last) const {
    std::vector<HeldFrame> frames(6, HeldFrame{obs, {}});
    for (HeldFrame& f : frames) f.step.pose = first;
    frames.back().step.pose = last;
    return frames;
  }
  // The same, but the person 0.6 m away on the last frame, as after a jump the tracker cannot
  // follow back.
  std::vector<HeldFrame> held_ending_away(const StickPose& first) const {
    StickPose away = truth;
    away.t0.x() += 0.6;
    std::vector<HeldFrame> frames = held(first, away);
    // The observation's views point at the rig's cameras: the pointer keeps them alive.
    const auto rig_away = std::make_shared<const testing::RigObservation>(observe(away));
    frames.back().obs = std::shared_ptr<const Observation>(rig_away, &rig_away->observation);
    return frames;
  }
};

// As tracked while the body was a guess: the trunk 4 cm forward, the arms swung 0.4 rad.
StickPose off_from(StickPose pose) {
  pose.t0 += Eigen::Vector3d(0, 0, 0.04);
  pose.theta[kLShoulder2] += 0.4;
  pose.theta[kRShoulder2] -= 0.4;
  return pose;
}

TrackerOptions unfiltered() {
  TrackerOptions options;
  options.use_filter = false;
  return options;
}

TEST(TrackBack, FramesTrackedOffComeBackToWhereTheLastOneIs) {
  const Rig r;
  const StickPose off = off_from(r.truth);
  ASSERT_GT(testing::max_joint_error(r.model, off, r.truth), 0.15);
  std::vector<HeldFrame> frames = r.held(off, r.truth);
  track_back(r.dims, r.surface, unfiltered(), frames);
  // The capsules' fit itself leaves a few centimetres on the worst point from the truth.
  for (const HeldFrame& f : frames)
    EXPECT_LT(testing::max_joint_error(r.model, f.step.pose, r.truth), 0.08);
}

TEST(TrackBack, AFrameTheForwardPassExplainsBetterKeepsItsPose) {
  const Rig r;
  // Where the forward pass settles on the first frames: the capsules' own least cost.
  const StickPose settled =
      testing::track_repeated(r.dims, r.surface, unfiltered(), r.truth, *r.obs, 5);
  std::vector<HeldFrame> frames = r.held_ending_away(settled);
  track_back(r.dims, r.surface, unfiltered(), frames);
  for (size_t i = 0; i + 1 < frames.size(); ++i)
    EXPECT_LT(testing::max_joint_error(r.model, frames[i].step.pose, settled), 0.01)
        << "frame " << i;
}

TEST(TrackBack, FramesBeforeOneTheForwardPassExplainsBetterAreTrackedBackFromIt) {
  const Rig r;
  const StickPose settled =
      testing::track_repeated(r.dims, r.surface, unfiltered(), r.truth, *r.obs, 5);
  // The forward pass off on the first frames, settled on the one before the last (which the
  // backward pass, coming from 0.6 m away, cannot follow): left to itself it stays 4-7 cm off.
  std::vector<HeldFrame> frames = r.held_ending_away(off_from(settled));
  frames[frames.size() - 2].step.pose = settled;
  track_back(r.dims, r.surface, unfiltered(), frames);
  for (size_t i = 0; i + 1 < frames.size(); ++i)
    EXPECT_LT(testing::max_joint_error(r.model, frames[i].step.pose, settled), 0.01)
        << "frame " << i;
}

}  // namespace
}  // namespace simcap::tracker
