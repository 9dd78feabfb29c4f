// The silhouette-ray cues of the fit: the ray-to-stick geometry, radii measured from rays, and
// the refinement pulling a displaced limb back onto the rays of its silhouette.
#include <gtest/gtest.h>

#include <random>

#include "tests/tracker/ray_rig.h"
#include "tests/tracker/refine_test_support.h"
#include "tracker/icp_targets.h"
#include "tracker/pose_init.h"
#include "tracker/pose_refiner.h"

namespace simcap::tracker {
namespace {

using testing::segment_distance;
using testing::silhouette_rays;
using testing::walking_pose;

TEST(NearestOnRay, MatchesADenseSearchAlongTheRay) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    const SilhouetteRay ray{Eigen::Vector3d(4 * u(rng), 3 + u(rng), 4 * u(rng)),
                            Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized()};
    const Eigen::Vector3d q = nearest_on_ray(ray, a, b);
    EXPECT_NEAR((q - ray.origin).cross(ray.direction).norm(), 0.0, 1e-9) << "not on the ray";
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 200000; ++i) {
      best = std::min(best, segment_distance(ray.origin + 1e-4 * i * ray.direction, a, b));
    }
    EXPECT_LE(segment_distance(q, a, b), best + 1e-6) << trial;
  }
}

TEST(MeasureRadii, RecoversTheRadiiOfCapsulesFromTheirRays) {
  const BodyDimensions truth = testing::capsule_body();
  const StickModel model(truth, JointSet::urdf);
  const StickPose pose = walking_pose();
  const auto rays = silhouette_rays(model, pose, 2);
  BodyDimensions measured = truth;
  measured.radius.fill(0);
  measured.torso_width = 0;
  measure_radii(measured, JointSet::urdf, pose, rays);
  for (int s = 0; s < kSegmentCount; ++s) {
    EXPECT_NEAR(measured.radius[s], truth.radius[s], 0.2 * truth.radius[s]) << segment_name(s);
  }
  EXPECT_NEAR(measured.torso_width, truth.torso_width, 0.2 * truth.torso_width);
}

TEST(PoseRefiner, SilhouetteRaysPullADisplacedArmBack) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  const StickPose truth = walking_pose();
  IcpTargets targets;
  targets.rays = silhouette_rays(model, truth, 3);
  ASSERT_GT(targets.rays.size(), 500u);
  StickPose pose = truth;
  pose.theta[kLShoulder1] = 0.15;  // the arm swung 0.35 rad towards the torso
  pose.theta[kLElbow] = -0.2;
  const PoseRefiner refiner(model, testing::converging_without_priors());
  const auto hand = [&](const StickPose& p) {
    return model.reference_points(model.geometry(p))[kLHandTip];
  };
  const double before = (hand(pose) - hand(truth)).norm();
  ASSERT_GT(before, 0.15);
  const double cost_before = refiner.cost(targets, pose);
  refiner.refine(targets, pose);
  EXPECT_LT(refiner.cost(targets, pose), 0.1 * cost_before);
  EXPECT_LT((hand(pose) - hand(truth)).norm(), 0.04);
}

}  // namespace
}  // namespace simcap::tracker
