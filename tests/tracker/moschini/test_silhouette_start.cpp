// The silhouette start: where the hull merges parts, the centerline's centroids can describe
// another pose than the silhouettes do, and the refinement they lead stays in that pose's basin;
// the fit the silhouettes alone make from the previous pose keeps the right one.
#include <gtest/gtest.h>

#include <utility>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tests/tracker/moschini/track_support.h"
#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {
namespace {

TEST(SilhouetteStart, KeepsThePoseTheSilhouettesShowWhenTheCenterlineShowsAnother) {
  const BodyDimensions dims = testing::capsule_body();
  const BodySurface surface = testing::capsule_surface();
  const StickModel model(dims, JointSet::urdf);
  const StickPose truth = testing::walking_pose();
  const Eigen::AlignedBox3d volume = testing::volume_around(truth);
  // The centerline of the pose with the arms' and the legs' swing exchanged.
  StickPose other = truth;
  for (const auto& [l, r] : {std::pair{kLShoulder1, kRShoulder1},
                             {kLShoulder2, kRShoulder2},
                             {kLElbow, kRElbow},
                             {kLHip2, kRHip2},
                             {kLKnee, kRKnee}}) {
    std::swap(other.theta[l], other.theta[r]);
  }
  const testing::RigObservation rig =
      testing::observe_rig_misled(model, surface, truth, other, testing::camera_ring(4), volume);

  // Five frames of that observation from the truth; the worst error over elbows, hands, knees
  // and ankles.
  auto worst_error = [&](int iterations) {
    TrackerOptions options;
    options.silhouette_start.iterations = iterations;
    const StickPose pose =
        testing::track_repeated(dims, surface, options, truth, rig.observation, 5);
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
