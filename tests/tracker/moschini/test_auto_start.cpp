// --init auto's body: proportions measured on the first frames of a person standing upright.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/tracker/moschini/ray_rig.h"
#include "tracker/moschini/auto_start.h"
#include "tracker/moschini/grid_search.h"
#include "tracker/moschini/pose_init.h"

namespace simcap::tracker {
namespace {

// The humanoid's proportions for 1.75 m, its shoulders raised as CMU 131_01 carries them.
TEST(AutoStart, MeasuresTheShouldersHeight) {
  BodyDimensions truth = dimensions_from_height(1.75);
  truth.d_s = 1.15;
  const BodySurface surface = typical_surface(truth);
  const StickModel model(truth, JointSet::urdf);
  StickPose pose;
  pose.R0 = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()).toRotationMatrix();
  pose.t0 = {0.2, 0.0, -0.1};
  // Standing on the floor: the ankles 3.9% of stature up.
  pose.t0.y() = 0.039 * 1.75 + truth.calf + truth.thigh + truth.torso_half;
  pose.theta[kLShoulder1] = 0.15;
  pose.theta[kRShoulder1] = -0.15;
  pose.theta[kLElbow] = pose.theta[kRElbow] = -0.3;
  const testing::RigObservation rig = testing::observe_rig(
      model, surface, pose, testing::camera_ring(6),
      Eigen::AlignedBox3d(Eigen::Vector3d(-1.0, 0.0, -1.3), Eigen::Vector3d(1.4, 2.1, 1.1)));
  const Observation& obs = rig.observation;
  ASSERT_GT(obs.hull.count, 1000);

  TrackerOptions options;
  options.use_filter = false;
  const AutoStart start = auto_start({obs, obs, obs}, options);
  EXPECT_NEAR(start.dims.d_s, truth.d_s, 0.08);
  EXPECT_NEAR(start.dims.thigh, truth.thigh, 0.03 * truth.thigh);
  const StickModel found(start.dims, JointSet::urdf);
  const auto r = found.reference_points(found.geometry(start.pose));
  const auto t = model.reference_points(model.geometry(pose));
  for (const int point : {kLShoulderPoint, kRShoulderPoint, kLHipPoint, kNeckPoint}) {
    EXPECT_LT((r[point] - t[point]).norm(), 0.03) << "reference point " << point;
  }
}

// Where --init auto's refit expects the lowest ankle: Winter's anthropometric table puts the
// ankle at 0.039 of the stature above the floor.
TEST(AutoStart, AnkleHeightIsWintersFractionOfTheStature) {
  for (const double height : {1.5, 1.75, 2.0}) {
    EXPECT_NEAR(ankle_height_from_height(height), 0.039 * height, 0.005) << height;
  }
}

// A parabola's vertex is found exactly wherever it lies between the grid's points; with noise
// a tenth of the valley's depth it is found within 0.01 (a golden-section search of 8
// evaluations stops at 0.89), and a least beyond the range's end gives the end.
TEST(LeastOnGrid, FindsTheLeastOfAShallowNoisyValley) {
  auto parabola = [](double x) { return (x - 0.93) * (x - 0.93); };
  EXPECT_NEAR(least_on_grid(parabola, 0.75, 1.35, 13), 0.93, 1e-12);
  const double noise = 0.1 * 0.15 * 0.15;
  auto noisy = [&](double x) { return parabola(x) + noise * std::sin(97 * x); };
  EXPECT_NEAR(least_on_grid(noisy, 0.75, 1.35, 13), 0.93, 0.01);
  const double at_end = least_on_grid(parabola, 1.0, 1.6, 13);
  EXPECT_GE(at_end, 1.0);
  EXPECT_LE(at_end, 1.05);
}

}  // namespace
}  // namespace simcap::tracker
