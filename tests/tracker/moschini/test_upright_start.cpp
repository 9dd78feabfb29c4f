// Where --init auto and recovery start: upright hypotheses around the circle, fitted, then each
// limb restarted from typical configurations. A body that is not standing neutrally (an arm
// across the front, the legs in stride) is found from its silhouettes alone.
#include <gtest/gtest.h>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {
namespace {

// Facing 0.7 rad off +Z, the left forearm across the front, the right thigh forward.
StickPose arm_across_in_stride() {
  StickPose p;
  p.t0 = {0.1, 1.05, -0.2};
  p.R0 = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY()).toRotationMatrix();
  p.theta[kLShoulder1] = 0.1;
  p.theta[kLShoulder2] = -0.3;
  p.theta[kLShoulder3] = 0.8;
  p.theta[kLElbow] = -1.8;
  p.theta[kRShoulder1] = -0.15;
  p.theta[kRElbow] = -0.3;
  p.theta[kRHip2] = -0.35;
  p.theta[kRKnee] = 0.3;
  p.theta[kLHip2] = 0.2;
  p.theta[kLKnee] = 0.15;
  return p;
}

TEST(MoschiniTracker, UprightStartFindsAnArmAcrossTheBody) {
  const BodyDimensions dims = testing::capsule_body();
  const BodySurface surface = testing::capsule_surface();
  const StickModel model(dims, JointSet::urdf);
  const StickPose truth = arm_across_in_stride();
  // Four cameras: with six, the fit finds the arm without the limbs' search.
  const testing::RigObservation rig =
      testing::observe_rig(model, surface, truth, testing::camera_ring(4),
                           Eigen::AlignedBox3d(truth.t0 - Eigen::Vector3d(1.2, 1.05, 1.2),
                                               truth.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)));
  const Observation& obs = rig.observation;
  ASSERT_GT(obs.points.size(), 50u);

  TrackerOptions options;
  options.use_filter = false;
  MoschiniTracker tracker(dims, surface, options);
  tracker.start_upright(obs);
  const StickPose found = tracker.step(obs).pose;
  const auto r = model.reference_points(model.geometry(found));
  const auto t = model.reference_points(model.geometry(truth));
  for (const int point : {kLHandTip, kLElbowPoint, kRKneePoint, kRAnklePoint, kHeadTip}) {
    EXPECT_LT((r[point] - t[point]).norm(), 0.06) << "reference point " << point;
  }
  const Eigen::Vector3d forward = found.R0.col(2), true_forward = truth.R0.col(2);
  EXPECT_GT(forward.dot(true_forward), std::cos(0.25));
}

}  // namespace
}  // namespace simcap::tracker
