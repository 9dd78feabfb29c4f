// The silhouette start: where the hull merges parts, the centerline's centroids can describe
// another pose than the silhouettes do, and the refinement they lead stays in that pose's basin;
// the fit the silhouettes alone make from the previous pose keeps the right one.
#include <gtest/gtest.h>

#include <utility>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {
namespace {

TEST(SilhouetteStart, KeepsThePoseTheSilhouettesShowWhenTheCenterlineShowsAnother) {
  const BodyDimensions dims = testing::capsule_body();
  const BodySurface surface = testing::capsule_surface();
  const StickModel model(dims, JointSet::urdf);
  const StickPose truth = testing::walking_pose();
  const Eigen::AlignedBox3d volume(truth.t0 - Eigen::Vector3d(1.2, 1.1, 1.2),
                                   truth.t0 + Eigen::Vector3d(1.2, 1.0, 1.2));
  testing::RigObservation rig =
      testing::observe_rig(model, surface, truth, testing::camera_ring(4), volume);
  // The centerline of the pose with the arms' and the legs' swing exchanged.
  StickPose other = truth;
  for (const auto& [l, r] : {std::pair{kLShoulder1, kRShoulder1},
                             {kLShoulder2, kRShoulder2},
                             {kLElbow, kRElbow},
                             {kLHip2, kRHip2},
                             {kLKnee, kRKnee}}) {
    std::swap(other.theta[l], other.theta[r]);
  }
  rig.observation.points =
      testing::observe_rig(model, surface, other, testing::camera_ring(4), volume)
          .observation.points;

  // Five frames of that observation from the truth; the worst error over elbows, hands, knees
  // and ankles.
  auto worst_error = [&](int iterations) {
    TrackerOptions options;
    options.use_filter = false;
    options.silhouette_start.iterations = iterations;
    MoschiniTracker tracker(dims, surface, options);
    tracker.start(truth);
    StickPose pose;
    for (int frame = 0; frame < 5; ++frame) pose = tracker.step(rig.observation).pose;
    const auto r = model.reference_points(model.geometry(pose));
    const auto t = model.reference_points(model.geometry(truth));
    double worst = 0;
    for (const int p : {kLElbowPoint, kRElbowPoint, kLHandTip, kRHandTip, kLKneePoint, kRKneePoint,
                        kLAnklePoint, kRAnklePoint}) {
      worst = std::max(worst, (r[p] - t[p]).norm());
    }
    return worst;
  };
  const TrackerOptions defaults;
  EXPECT_LT(worst_error(defaults.silhouette_start.iterations), 0.02);
  // Without it the centerline leads the limbs away.
  EXPECT_GT(worst_error(0), 0.2);
}

}  // namespace
}  // namespace simcap::tracker
