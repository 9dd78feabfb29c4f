// The arm search on an unexplained silhouette: an arm the tracker holds against the trunk while
// the cameras see it raised is found again once its silhouette is left unexplained.
#include <gtest/gtest.h>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tests/tracker/moschini/track_support.h"
#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {
namespace {

TEST(UnexplainedSilhouette, AnArmLostAgainstTheTrunkIsFoundAgain) {
  const BodyDimensions dims = testing::capsule_body();
  const BodySurface surface = testing::capsule_surface();
  const StickModel model(dims, JointSet::urdf);
  StickPose truth = testing::walking_pose();
  truth.theta[kRShoulder2] = -1.2;  // the right arm raised forward
  truth.theta[kRElbow] = -0.5;
  StickPose lost = truth;  // ...held hanging against the trunk, as a lost arm is
  lost.theta[kRShoulder1] = lost.theta[kRShoulder2] = lost.theta[kRShoulder3] = 0.0;
  lost.theta[kRElbow] = -0.2;
  const Eigen::AlignedBox3d volume = testing::volume_around(truth);
  // The centerline as the lost pose has it, so that the joint refinement holds the arm down.
  const testing::RigObservation rig =
      testing::observe_rig_misled(model, surface, truth, lost, testing::camera_ring(4), volume);

  auto hand_error = [&](double fraction) {
    TrackerOptions options;
    options.unexplained.fraction = fraction;
    const StickPose pose =
        testing::track_repeated(dims, surface, options, lost, rig.observation, 4);
    const auto r = model.reference_points(model.geometry(pose));
    const auto t = model.reference_points(model.geometry(truth));
    return (r[kRHandTip] - t[kRHandTip]).norm();
  };
  EXPECT_LT(hand_error(TrackerOptions{}.unexplained.fraction), 0.05);
  EXPECT_GT(hand_error(0), 0.2);  // without the search the arm stays down
}

// A pose that explains its silhouettes starts no search: the tracker's result is the same with
// the search off.
TEST(UnexplainedSilhouette, AnExplainedSilhouetteStartsNoSearch) {
  const BodyDimensions dims = testing::capsule_body();
  const BodySurface surface = testing::capsule_surface();
  const StickModel model(dims, JointSet::urdf);
  const StickPose truth = testing::walking_pose();
  const Eigen::AlignedBox3d volume = testing::volume_around(truth);
  const testing::RigObservation rig =
      testing::observe_rig(model, surface, truth, testing::camera_ring(4), volume);
  auto track = [&](double fraction) {
    TrackerOptions options;
    options.unexplained.fraction = fraction;
    return testing::track_repeated(dims, surface, options, truth, rig.observation, 3);
  };
  const StickPose with = track(TrackerOptions{}.unexplained.fraction), without = track(0);
  EXPECT_EQ(with.theta, without.theta);
  EXPECT_EQ(with.t0, without.t0);
}

}  // namespace
}  // namespace simcap::tracker
