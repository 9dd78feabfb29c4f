// --init auto's first frames tracked again backwards once the body is measured: frames the
// forward pass left off come back to the pose the last one holds, and a frame the forward pass
// explains better keeps its pose.
#include <gtest/gtest.h>

#include <memory>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tests/tracker/moschini/track_support.h"
#include "tracker/moschini/track_back.h"

namespace simcap::tracker {
namespace {

struct Rig {
  BodyDimensions dims = testing::capsule_body();
  BodySurface surface = testing::capsule_surface();
  StickModel model{dims, JointSet::urdf};
  StickPose truth = testing::walking_pose();
  testing::RigObservation rig =
      testing::observe_rig(model, surface, truth, testing::camera_ring(4),
                           Eigen::AlignedBox3d(truth.t0 - Eigen::Vector3d(1.2, 1.05, 1.2),
                                               truth.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)));
  std::shared_ptr<const Observation> obs = std::make_shared<Observation>(rig.observation);

  // Six frames of the same observation, the forward pass's steps `first` and then `last`.
  std::vector<HeldFrame> held(const StickPose& first, const StickPose& last) const {
    std::vector<HeldFrame> frames(6, HeldFrame{obs, {}});
    for (HeldFrame& f : frames) f.step.pose = first;
    frames.back().step.pose = last;
    return frames;
  }
};

TEST(TrackBack, FramesTrackedOffComeBackToWhereTheLastOneIs) {
  const Rig r;
  // As tracked while the body was a guess: the trunk 4 cm forward, the arms swung 0.4 rad.
  StickPose off = r.truth;
  off.t0 += Eigen::Vector3d(0, 0, 0.04);
  off.theta[kLShoulder2] += 0.4;
  off.theta[kRShoulder2] -= 0.4;
  ASSERT_GT(testing::max_joint_error(r.model, off, r.truth), 0.15);
  std::vector<HeldFrame> frames = r.held(off, r.truth);
  TrackerOptions options;
  options.use_filter = false;
  track_back(r.dims, r.surface, options, frames);
  // The capsules' fit itself leaves a few centimetres on the worst point from the truth.
  for (const HeldFrame& f : frames)
    EXPECT_LT(testing::max_joint_error(r.model, f.step.pose, r.truth), 0.08);
}

TEST(TrackBack, AFrameTheForwardPassExplainsBetterKeepsItsPose) {
  const Rig r;
  // The person 0.6 m away on the last frame, as after a jump the tracker cannot follow back.
  StickPose away = r.truth;
  away.t0.x() += 0.6;
  const testing::RigObservation there =
      testing::observe_rig(r.model, r.surface, away, testing::camera_ring(4),
                           Eigen::AlignedBox3d(away.t0 - Eigen::Vector3d(1.2, 1.05, 1.2),
                                               away.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)));
  TrackerOptions options;
  options.use_filter = false;
  // Where the forward pass settles on the first frames: the capsules' own least cost.
  const StickPose settled = testing::track_repeated(r.dims, r.surface, options, r.truth, *r.obs, 5);
  std::vector<HeldFrame> frames = r.held(settled, away);
  frames.back().obs = std::make_shared<Observation>(there.observation);
  track_back(r.dims, r.surface, options, frames);
  for (size_t i = 0; i + 1 < frames.size(); ++i)
    EXPECT_LT(testing::max_joint_error(r.model, frames[i].step.pose, settled), 0.01)
        << "frame " << i;
}

}  // namespace
}  // namespace simcap::tracker
