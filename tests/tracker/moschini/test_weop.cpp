#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <random>

#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/weop.h"

namespace simcap::tracker {
namespace {

Eigen::Matrix3Xd random_points(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix3Xd A(3, n);
  for (int i = 0; i < n; ++i) A.col(i) = Eigen::Vector3d(u(rng), u(rng), u(rng));
  return A;
}

TEST(Weop, RecoversARigidMotionWhenOutliersHaveZeroWeight) {
  std::mt19937 rng(5);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(0.3, -1.0, 2.0);
  const int n = 40;
  const Eigen::Matrix3Xd A = random_points(n, rng);
  Eigen::Matrix3Xd B = (R * A).colwise() + t;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(n);
  // A quarter of the pairs are wrong by up to metres; X84 on the residuals of the true motion
  // would flag them, so their weight is 0 as in Alg. 2 step 5.
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int i = 0; i < n; i += 4) {
    B.col(i) += Eigen::Vector3d(u(rng), u(rng), u(rng));
    w(i) = 0.0;
  }
  const RigidMotion m = weop(A, B, w);
  EXPECT_LT((m.R - R).norm(), 1e-9);
  EXPECT_LT((m.t - t).norm(), 1e-9);
  EXPECT_NEAR(m.R.determinant(), 1.0, 1e-12);
}

TEST(Weop, WeightsTradeOffInconsistentPairs) {
  std::mt19937 rng(6);
  // Every point twice: once where it is, once shifted. No rotation can help either copy, so the
  // answer is a pure translation.
  const Eigen::Matrix3Xd P = random_points(15, rng);
  Eigen::Matrix3Xd A(3, 30), B(3, 30);
  A << P, P;
  const Eigen::Vector3d shift(0.5, 0, 0);
  B << P, P.colwise() + shift;
  Eigen::VectorXd w = Eigen::VectorXd::Ones(30);
  w.tail(15).setConstant(std::sqrt(3.0));  // effective weight W² = 3 on the shifted copy
  const RigidMotion m = weop(A, B, w);
  // The weighted least-squares translation is the W²-weighted mean shift: 3/4 of it.
  EXPECT_LT((m.t - 0.75 * shift).norm(), 1e-9);
  EXPECT_LT((m.R - Eigen::Matrix3d::Identity()).norm(), 1e-9);
}

TEST(Weop, NeverReturnsAReflection) {
  // Mirror-image data: the best orthogonal matrix would be a reflection.
  std::mt19937 rng(8);
  const Eigen::Matrix3Xd A = random_points(20, rng);
  const Eigen::Matrix3Xd B = Eigen::Vector3d(-1, 1, 1).asDiagonal() * A;
  const Eigen::Matrix3d R = wopp(A, B, Eigen::VectorXd::Ones(20));
  EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
  EXPECT_LT((R.transpose() * R - Eigen::Matrix3d::Identity()).norm(), 1e-12);
}

TEST(Weop, WoppRotatesAboutTheOrigin) {
  std::mt19937 rng(9);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(-0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Matrix3Xd A = random_points(10, rng);
  EXPECT_LT((wopp(A, R * A, Eigen::VectorXd::Ones(10)) - R).norm(), 1e-9);
  EXPECT_TRUE(wopp(A, A, Eigen::VectorXd::Zero(10)).isIdentity());
}

TEST(X84, RejectsOnlyTheFarTail) {
  std::vector<double> d;
  for (int i = 0; i < 100; ++i) d.push_back(0.01 + 0.0001 * i);
  d.push_back(0.5);
  const double limit = x84_threshold(d, 3.5, 0.0);
  EXPECT_GT(limit, 0.0199);  // every inlier survives
  EXPECT_LT(limit, 0.5);     // the outlier does not
  // Of 101 values the median is the 51st, 0.0150; MAD 0.0025: the rule's own threshold is 0.0280.
  EXPECT_NEAR(limit, 0.0150 + 3.5 * 1.4826 * 0.0025, 1e-9);
  EXPECT_DOUBLE_EQ(x84_threshold({0.001, 0.001, 0.001}, 3.5, 0.02), 0.02);
}

}  // namespace
}  // namespace simcap::tracker
