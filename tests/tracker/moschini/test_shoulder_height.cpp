// --init auto's second measurement of the shoulders' height: arms refitted with the trunk held
// find the height they hang from, from shoulders set too high or too low.
#include <gtest/gtest.h>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tests/tracker/moschini/track_support.h"
#include "tracker/moschini/shoulder_height.h"

namespace simcap::tracker {
namespace {

TEST(ShoulderHeight, ArmsRefittedWithTheTrunkHeldFindTheShouldersHeight) {
  BodyDimensions truth = testing::capsule_body();
  truth.d_s = 0.9;
  const BodySurface surface = testing::capsule_surface();
  const StickModel model(truth, JointSet::urdf);
  StickPose swinging = testing::walking_pose();
  StickPose forward = swinging;  // both arms raised forward, elbows bent
  forward.theta[kLShoulder1] = forward.theta[kRShoulder1] = 0.1;
  forward.theta[kLShoulder2] = forward.theta[kRShoulder2] = -1.0;
  forward.theta[kLElbow] = forward.theta[kRElbow] = -0.5;
  StickPose apart = swinging;  // both arms held out to the sides
  apart.theta[kLShoulder1] = 1.0;
  apart.theta[kRShoulder1] = -1.0;
  // The rigs hold the cameras each observation's views point at: alive, and not moved, while the
  // frames are in use.
  std::vector<testing::RigObservation> rigs;
  rigs.reserve(3);
  std::vector<TrackedObservation> frames;
  for (const StickPose& pose : {swinging, forward, apart}) {
    rigs.push_back(testing::observe_rig(model, surface, pose, testing::camera_ring(4),
                                        testing::volume_around(pose)));
    frames.push_back({std::make_shared<const Observation>(rigs.back().observation), pose});
  }
  TrackerOptions options;
  options.joints = JointSet::urdf;
  for (const double start : {0.78, 1.1}) {
    BodyDimensions wrong = truth;
    wrong.d_s = start;
    const ShoulderHeight found =
        shoulders_from_arms(wrong, surface, options, frames, 0.75, 1.35, 13);
    EXPECT_NEAR(found.d_s, truth.d_s, 0.03) << "from " << start;
    // The trunk, head and legs stay where the frame's pose has them.
    EXPECT_EQ(found.last.t0, apart.t0);
    EXPECT_EQ(found.last.R0, apart.R0);
    for (const int held : {kNeck2, kLHip2, kRKnee, kSpineFlexion})
      EXPECT_EQ(found.last.theta[held], apart.theta[held]);
  }
}

}  // namespace
}  // namespace simcap::tracker
