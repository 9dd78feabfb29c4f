// The Jacobian updates of Table 10's baselines against independent formulas: the pseudoinverse
// against Eigen's complete orthogonal decomposition, DLS by SVD against the normal equations, SDLS
// against the pseudoinverse where its clamps do not act, SDLS's clamps where they do, and PIK's
// priorities: a lower level never moves a higher one.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <numbers>
#include <random>
#include <vector>

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

// 15 rows (an error) by default; 40 for a joint-space step.
Eigen::VectorXd random_error(unsigned seed, double scale, int size = 15) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, scale);
  Eigen::VectorXd e(size);
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
  EXPECT_EQ(jacobian_update_name(JacobianUpdate::kPrioritized), "pik");
}

TEST(JacobianStep, LowerPrioritiesDoNotDisturbHigherOnes) {
  const Eigen::MatrixXd j = random_jacobian(11);
  const Eigen::VectorXd e = random_error(12, 0.3);
  const Eigen::VectorXd z = random_error(13, 0.1, 40);
  const std::vector<int> levels = {6, 6, 3};
  for (double lambda : {0.0, 0.05, 0.75}) {
    const Eigen::VectorXd full = prioritized_step(j, e, levels, lambda, z);
    // Each level alone with the ones above: what it adds leaves J_i dq of those unchanged.
    Eigen::Index rows = 0;
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
      rows += levels[k];
      const std::vector<int> above(levels.begin(), levels.begin() + static_cast<long>(k) + 1);
      const Eigen::VectorXd partial =
          prioritized_step(j.topRows(rows), e.head(rows), above, lambda, Eigen::VectorXd::Zero(40));
      EXPECT_LT((j.topRows(rows) * (full - partial)).norm(), 1e-9)
          << "lambda " << lambda << ", levels 1-" << k + 1;
    }
  }
}

TEST(JacobianStep, PrioritizedOneLevelIsDlsBySvd) {
  const Eigen::MatrixXd j = random_jacobian(14);
  const Eigen::VectorXd e = random_error(15, 0.05);
  const Eigen::VectorXd svd = jacobian_step(JacobianUpdate::kDlsSvd, j, e, 0.75);
  const Eigen::VectorXd pik = prioritized_step(j, e, {15}, 0.75, Eigen::VectorXd::Zero(40));
  EXPECT_LT((pik - svd).norm(), 1e-12 * svd.norm());
}

TEST(JacobianStep, PrioritizedUndampedSolvesTheTopLevelExactly) {
  // 40 joints, 15 rows: every level is reachable, so undamped each is met in turn.
  const Eigen::MatrixXd j = random_jacobian(16);
  const Eigen::VectorXd e = random_error(17, 0.05);
  const Eigen::VectorXd step = prioritized_step(j, e, {6, 6, 3}, 0.0, random_error(18, 0.1, 40));
  EXPECT_LT((j * step - e).norm(), 1e-9);
  // A conflicting lower level (a copy of a top row asking for something else) gives way.
  Eigen::MatrixXd conflict(7, 40);
  conflict << j.topRows(6), j.row(0);
  Eigen::VectorXd wanted(7);
  wanted << e.head(6), e[0] + 1.0;
  const Eigen::VectorXd given =
      prioritized_step(conflict, wanted, {6, 1}, 0.0, Eigen::VectorXd::Zero(40));
  EXPECT_LT((j.topRows(6) * given - e.head(6)).norm(), 1e-9);
}

}  // namespace
}  // namespace simcap
