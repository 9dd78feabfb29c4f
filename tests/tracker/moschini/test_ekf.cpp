#include <gtest/gtest.h>

#include <random>

#include "tracker/moschini/ekf.h"

namespace simcap::tracker {
namespace {

StickPose some_pose(const StickModel& model) {
  StickPose p;
  p.t0 = {0.3, 1.1, -0.2};
  p.R0 = Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, 1, -0.2).normalized()).toRotationMatrix();
  std::mt19937 rng(4);
  for (int k = 0; k < model.angle_count(); ++k) {
    const auto& r = model.ranges()[k];
    p.theta[k] =
        std::uniform_real_distribution<double>(std::max(r.lo, -1.2), std::min(r.hi, 1.2))(rng);
  }
  return p;
}

TEST(PoseFilter, AnalyticJacobianMatchesFiniteDifferences) {
  for (JointSet set : {JointSet::moschini, JointSet::urdf}) {
    const StickModel model(BodyDimensions{}, set);
    PoseFilter filter(model);
    filter.reset(some_pose(model));
    EXPECT_EQ(filter.state_size(), set == JointSet::moschini ? 23 : 34);
    // Away from the reference so that the rotation-vector part is exercised too.
    PoseFilter::State x = filter.state();
    x.segment<3>(3) = Eigen::Vector3d(0.2, -0.1, 0.3);
    const PoseFilter::Jacobian H = filter.jacobian(x);
    const double h = 1e-6;
    for (int j = 0; j < x.size(); ++j) {
      PoseFilter::State xp = x, xm = x;
      xp(j) += h;
      xm(j) -= h;
      const PoseFilter::Measurement numeric = (filter.measure(xp) - filter.measure(xm)) / (2 * h);
      EXPECT_LT((H.col(j) - numeric).norm(), 1e-6) << "state " << j;
    }
  }
}

TEST(PoseFilter, CorrectionMovesTowardsTheMeasurementAndKeepsLimits) {
  const StickModel model(BodyDimensions{}, JointSet::moschini);
  PoseFilter filter(model);
  const StickPose start = some_pose(model);
  filter.reset(start);
  StickPose target = start;
  target.t0 += Eigen::Vector3d(0.05, 0, 0.03);
  target.theta[kLElbow] = std::max(model.ranges()[kLElbow].lo, start.theta[kLElbow] - 0.3);
  const auto z = model.reference_points(model.geometry(target));
  auto error = [&](const StickPose& p) {
    const auto q = model.reference_points(model.geometry(p));
    double e = 0;
    for (int i = 0; i < kReferencePointCount; ++i) e += (q[i] - z[i]).norm();
    return e;
  };
  const double before = error(filter.pose());
  for (int i = 0; i < 5; ++i) {
    filter.predict();
    filter.correct(z);
  }
  EXPECT_LT(error(filter.pose()), 0.1 * before);
  for (int k = 0; k < model.angle_count(); ++k) {
    EXPECT_GE(filter.pose().theta[k], model.ranges()[k].lo - 1e-12);
    EXPECT_LE(filter.pose().theta[k], model.ranges()[k].hi + 1e-12);
  }
}

}  // namespace
}  // namespace simcap::tracker
