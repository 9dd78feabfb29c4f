// The silhouette cues of the fit: the ray-to-stick geometry, the capsules fitted to one frame's
// rays and outlines, and the refinement pulling a displaced limb back onto the rays of its
// silhouette.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/moschini_tracker.h"
#include "tracker/moschini/pose_refiner.h"
#include "tracker/moschini/silhouette_view.h"
#include "tracker/moschini/surface_fit.h"

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

// A body thinner and stouter than average in places, its chest carried further forward: the
// fit on one frame (rays and outlines from six cameras) starts from the typical capsules and
// recovers the body's own.
TEST(FitSurface, RecoversTheCapsulesOfAnotherBody) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  const BodySurface typical = testing::capsule_surface();
  BodySurface truth = typical;
  for (int c = 0; c < kCapsuleCount; ++c) {
    const std::string_view name = capsule_name(c);
    const double scale = name.ends_with("thigh") ? 1.25 : name.ends_with("upperarm") ? 0.8 : 1.0;
    truth[c].ra *= scale;
    truth[c].rb *= scale;
    if (name.starts_with("chest")) {
      truth[c].a.z() += 0.02;
      truth[c].b.z() += 0.02;
    }
  }
  const StickPose pose = walking_pose();
  const std::vector<double> azimuths = testing::camera_ring(6);
  const auto masks = testing::silhouette_masks(model, truth, pose, azimuths);
  std::vector<Camera> cams;
  std::vector<SilhouetteView> views;
  for (const double a : azimuths) cams.push_back(testing::ring_camera(pose, a));
  for (size_t c = 0; c < cams.size(); ++c) views.emplace_back(cams[c], masks[c]);
  const BodySurface fitted =
      fit_surface(model, pose, typical, silhouette_rays(model, truth, pose, 3), views);
  for (int c = 0; c < kCapsuleCount; ++c) {
    const std::string name(capsule_name(c));
    EXPECT_NEAR(fitted[c].ra, truth[c].ra, 0.1 * truth[c].ra + 0.003) << name;
    EXPECT_NEAR(fitted[c].rb, truth[c].rb, 0.1 * truth[c].rb + 0.003) << name;
  }
  // The chest moved 2 cm forward. Where the arms hang beside it its top is barely seen, and a
  // broader, narrower-set pair of capsules explains the views about as well (measured: the top
  // ends 1.1 cm short, 1.4 cm closer together, 1 cm broader).
  for (const int chest : {3, 4}) {
    EXPECT_NEAR(fitted[chest].a.z(), truth[chest].a.z(), 0.012) << capsule_name(chest);
    EXPECT_NEAR(fitted[chest].b.z(), truth[chest].b.z(), 0.012) << capsule_name(chest);
  }
  // Started from the truth itself, the fit stays there.
  const BodySurface kept =
      fit_surface(model, pose, truth, silhouette_rays(model, truth, pose, 3), views);
  for (int c = 0; c < kCapsuleCount; ++c) {
    EXPECT_NEAR(kept[c].ra, truth[c].ra, 0.004) << capsule_name(c);
    EXPECT_LT((kept[c].a - truth[c].a).norm(), 0.004) << capsule_name(c);
  }
}

TEST(PoseRefiner, SilhouetteRaysPullADisplacedArmBack) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  const StickPose truth = walking_pose();
  IcpTargets targets;
  targets.rays = silhouette_rays(model, testing::capsule_surface(), truth, 3);
  ASSERT_GT(targets.rays.size(), 500u);
  StickPose pose = truth;
  pose.theta[kLShoulder1] = 0.15;  // the arm swung 0.35 rad towards the torso
  pose.theta[kLElbow] = -0.2;
  const PoseRefiner refiner(model, testing::capsule_surface(),
                            testing::converging_without_priors());
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

// The rays are associated in parallel; the fit must not depend on how many threads share them.
TEST(PoseRefiner, FitsTheSameOnOneThreadAsOnSeveral) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  const StickPose truth = walking_pose();
  IcpTargets targets;
  targets.rays = silhouette_rays(model, testing::capsule_surface(), truth, 3);
  ASSERT_GT(targets.rays.size(), 512u);  // more than two of the association's blocks of rays
  StickPose start = truth;
  start.theta[kLShoulder1] = 0.15;
  start.theta[kLElbow] = -0.2;
  const PoseRefiner refiner(model, testing::capsule_surface(),
                            testing::converging_without_priors());
  auto fit = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    StickPose pose = start;
    refiner.refine(targets, pose);
    return std::pair{pose, refiner.cost(targets, pose)};
  };
  const auto [one, one_cost] = fit(1);
  for (const int threads : {2, 4}) {
    const auto [many, many_cost] = fit(threads);
    EXPECT_EQ(many.t0, one.t0) << threads;
    EXPECT_EQ(many.R0, one.R0) << threads;
    EXPECT_EQ(many.theta, one.theta) << threads;
    EXPECT_EQ(many_cost, one_cost) << threads;
  }
  EXPECT_GT(std::abs(one.theta[kLShoulder1] - start.theta[kLShoulder1]), 0.1);  // it did fit
}

// The gradient the normal equations build, against central differences of the cost itself,
// for every term but the outlines (whose targets refine() holds fixed on purpose): centerline
// points, stick samples off the hull, silhouette rays, and both priors. Two approximations of
// the fit are kept out of it: capsules are untapered (a ray's residual is measured across the
// axis, which ignores a taper's slope) and the motion prior's rotation is zero at the pose (its
// gradient takes the rotation vector as linear in the increment).
TEST(PoseRefiner, GradientMatchesFiniteDifferencesOfTheCost) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  BodySurface surface = testing::capsule_surface();
  for (CapsuleShape& c : surface) c.rb = c.ra;
  StickPose truth = walking_pose();
  const testing::RigObservation rig =
      testing::observe_rig(model, surface, truth, testing::camera_ring(4),
                           Eigen::AlignedBox3d(truth.t0 - Eigen::Vector3d(1.2, 1.05, 1.2),
                                               truth.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)));
  IcpTargets targets = MoschiniTracker::targets_of(rig.observation);
  targets.views = nullptr;
  StickPose pose = truth;  // away from the truth, so that every term has residuals
  pose.t0 += Eigen::Vector3d(0.03, -0.02, 0.025);
  pose.R0 = Eigen::AngleAxisd(0.08, Eigen::Vector3d(0.3, 1, 0.2).normalized()) * pose.R0;
  for (int k = 0; k < model.angle_count(); ++k) pose.theta[k] += 0.04 * ((k % 3) - 1);
  truth.R0 = pose.R0;
  targets.prediction = &truth;
  const PoseRefiner refiner(model, surface);
  ASSERT_GT(refiner.options().leg_prior_m_per_rad, 0);
  ASSERT_GT(refiner.options().motion_prior_m_per_rad, 0);
  const Eigen::VectorXd g = refiner.gradient(targets, pose);
  ASSERT_EQ(g.size(), 6 + model.angle_count());
  const double h = 1e-6;
  auto moved = [&](int k, double d) {
    StickPose p = pose;
    if (k < 3) {
      p.t0[k] += d;
    } else if (k < 6) {
      p.R0 = Eigen::AngleAxisd(d, Eigen::Vector3d::Unit(k - 3)) * p.R0;
    } else {
      p.theta[k - 6] += d;
    }
    return p;
  };
  for (int k = 0; k < g.size(); ++k) {
    const double fd =
        (refiner.cost(targets, moved(k, h)) - refiner.cost(targets, moved(k, -h))) / (2 * h);
    EXPECT_NEAR(g[k], fd, 1e-5 * g.cwiseAbs().maxCoeff()) << "parameter " << k;
  }
}

}  // namespace
}  // namespace simcap::tracker
