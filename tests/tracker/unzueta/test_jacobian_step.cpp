// The Jacobian updates of Table 10's baselines against independent formulas: the pseudoinverse
// against Eigen's complete orthogonal decomposition, DLS by SVD against the normal equations, SDLS
// against the pseudoinverse where its clamps do not act, and SDLS's clamps where they do.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <numbers>
#include <random>

#include "tracker/unzueta/jacobian_step.h"

namespace simcap {
namespace {

// A 15 x 40 Jacobian-sized matrix (five end-effectors, 40 degrees of freedom) with entries of a
// body's scale (decimetres per radian).
Eigen::MatrixXd random_jacobian(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 0.3);
  Eigen::MatrixXd j(15, 40);
  for (int r = 0; r < j.rows(); ++r)
    for (int c = 0; c < j.cols(); ++c) j(r, c) = normal(rng);
  return j;
}

Eigen::VectorXd random_error(unsigned seed, double scale) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, scale);
  Eigen::VectorXd e(15);
  for (int i = 0; i < e.size(); ++i) e[i] = normal(rng);
  return e;
}

TEST(JacobianStep, PseudoinverseIsTheMinimumNormSolution) {
  const Eigen::MatrixXd j = random_jacobian(1);
  const Eigen::VectorXd e = random_error(2, 0.05);
  const Eigen::VectorXd step = jacobian_step(JacobianUpdate::kPseudoinverse, j, e, 0.0);
  const Eigen::VectorXd expected = j.completeOrthogonalDecomposition().pseudoInverse() * e;
  EXPECT_LT((step - expected).norm(), 1e-9 * expected.norm());
  EXPECT_LT((j * step - e).norm(), 1e-9);  // full row rank: the error is removed exactly
}

TEST(JacobianStep, PseudoinverseIgnoresAZeroSingularDirection) {
  Eigen::MatrixXd j = random_jacobian(3);
  j.row(14) = j.row(13);  // a rank-deficient Jacobian: two equal rows
  Eigen::VectorXd e = random_error(4, 0.05);
  e[14] = e[13];
  const Eigen::VectorXd step = jacobian_step(JacobianUpdate::kPseudoinverse, j, e, 0.0);
  EXPECT_TRUE(step.allFinite());
  EXPECT_LT((j * step - e).norm(), 1e-9);
}

TEST(JacobianStep, DlsBySvdEqualsDlsByNormalEquations) {
  const Eigen::MatrixXd j = random_jacobian(5);
  const Eigen::VectorXd e = random_error(6, 0.05);
  for (double lambda : {0.05, 0.75, 3.0}) {
    const Eigen::VectorXd normal = jacobian_step(JacobianUpdate::kDls, j, e, lambda);
    const Eigen::VectorXd svd = jacobian_step(JacobianUpdate::kDlsSvd, j, e, lambda);
    EXPECT_LT((normal - svd).norm(), 1e-9 * normal.norm()) << "lambda " << lambda;
  }
}

TEST(JacobianStep, SdlsIsThePseudoinverseForSmallErrors) {
  const Eigen::MatrixXd j = random_jacobian(7);
  const Eigen::VectorXd e = random_error(8, 1e-5);
  const Eigen::VectorXd sdls = jacobian_step(JacobianUpdate::kSdls, j, e, 0.0);
  const Eigen::VectorXd pinv = jacobian_step(JacobianUpdate::kPseudoinverse, j, e, 0.0);
  ASSERT_LT(pinv.cwiseAbs().maxCoeff(), 0.01);  // far below every clamp
  EXPECT_LT((sdls - pinv).norm(), 1e-9 * pinv.norm());
}

TEST(JacobianStep, SdlsBoundsEveryJointTurn) {
  const Eigen::MatrixXd j = random_jacobian(9);
  const Eigen::VectorXd e = random_error(10, 5.0);  // metres: far out of one step's reach
  const Eigen::VectorXd pinv = jacobian_step(JacobianUpdate::kPseudoinverse, j, e, 0.0);
  ASSERT_GT(pinv.cwiseAbs().maxCoeff(), std::numbers::pi / 4);
  const Eigen::VectorXd step = sdls_step(j, e, std::numbers::pi / 4);
  EXPECT_LE(step.cwiseAbs().maxCoeff(), std::numbers::pi / 4 + 1e-12);
  EXPECT_GT(step.dot(j.transpose() * e), 0.0);  // still a descent direction for |e - J dq|^2
  const Eigen::VectorXd tight = sdls_step(j, e, 0.1);
  EXPECT_LE(tight.cwiseAbs().maxCoeff(), 0.1 + 1e-12);
}

TEST(JacobianStep, Names) {
  EXPECT_EQ(jacobian_update_name(JacobianUpdate::kPseudoinverse), "pinv");
  EXPECT_EQ(jacobian_update_name(JacobianUpdate::kDls), "dls");
  EXPECT_EQ(jacobian_update_name(JacobianUpdate::kDlsSvd), "dls-svd");
  EXPECT_EQ(jacobian_update_name(JacobianUpdate::kSdls), "sdls");
}

}  // namespace
}  // namespace simcap
