// Nelder-Mead on a known quadratic: it reaches the minimum inside the box, stops on the box's
// face when the minimum lies outside, and re-weighting the terms needs no new evaluation.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <atomic>

#include "tracker/gomez/nelder_mead.h"

namespace simcap::tracker::gomez {
namespace {

// f(x) = (x - c)^T A (x - c) with A symmetric positive definite, in 4 dimensions.
struct Quadratic {
  Eigen::Vector4d c{0.3, -0.2, 0.5, 0.1};
  Eigen::Matrix4d A;
  Quadratic() {
    Eigen::Matrix4d m;
    m << 2, 0.3, 0, 0.1, 0.3, 1, 0.2, 0, 0, 0.2, 3, 0.4, 0.1, 0, 0.4, 0.5;
    A = m;
  }
  double operator()(const Eigen::VectorXd& x) const {
    const Eigen::Vector4d d = x - c;
    return d.dot(A * d);
  }
};

TEST(NelderMead, FindsTheMinimumOfAQuadratic) {
  const Quadratic f;
  std::atomic<int> calls = 0;
  NelderMead nm(
      [&](const Eigen::VectorXd& x) {
        ++calls;
        return NelderMead::Terms(f(x), 0.0);
      },
      Eigen::VectorXd::Constant(4, -2), Eigen::VectorXd::Constant(4, 2), {.tolerance = 1e-14});
  nm.start(Eigen::VectorXd::Constant(4, 1.0), Eigen::VectorXd::Constant(4, 0.5));
  nm.set_weights({1.0, 0.0});
  const int used = nm.run(4000);
  EXPECT_LT((nm.best() - f.c).norm(), 1e-5);
  EXPECT_LT(nm.best_value(), 1e-10);
  EXPECT_TRUE(nm.converged());
  EXPECT_EQ(calls, 5 + used);
  EXPECT_EQ(nm.evaluations(), calls);
}

TEST(NelderMead, StaysInTheBox) {
  const Quadratic f;
  // Box excluding the minimum along the first coordinate: x0 <= 0.
  Eigen::VectorXd hi = Eigen::VectorXd::Constant(4, 2);
  hi[0] = 0.0;
  NelderMead nm([&](const Eigen::VectorXd& x) { return NelderMead::Terms(0.0, f(x)); },
                Eigen::VectorXd::Constant(4, -2), hi, {.tolerance = 1e-14});
  nm.start(Eigen::VectorXd::Constant(4, -1.0), Eigen::VectorXd::Constant(4, 0.5));
  nm.set_weights({0.0, 1.0});
  nm.run(4000);
  for (const Eigen::VectorXd& x : nm.history()) {
    EXPECT_LE(x[0], 0.0);
    EXPECT_GE(x.minCoeff(), -2.0);
  }
  // The constrained minimum: x0 = 0, the rest minimizing f with x0 fixed.
  const Eigen::Matrix3d A11 = f.A.bottomRightCorner<3, 3>();
  const Eigen::Vector3d rest =
      f.c.tail<3>() - A11.ldlt().solve(f.A.bottomLeftCorner<3, 1>() * (0.0 - f.c[0]));
  EXPECT_NEAR(nm.best()[0], 0.0, 1e-6);
  EXPECT_LT((nm.best().tail<3>() - rest).norm(), 1e-4);
}

TEST(NelderMead, ReweightingReordersWithoutEvaluating) {
  int calls = 0;
  NelderMead nm(
      [&](const Eigen::VectorXd& x) {
        ++calls;
        return NelderMead::Terms(x.squaredNorm(), (x - Eigen::VectorXd::Ones(2)).squaredNorm());
      },
      Eigen::VectorXd::Constant(2, -3), Eigen::VectorXd::Constant(2, 3));
  nm.start({Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(2, 0)});
  nm.set_weights({1.0, 0.0});
  EXPECT_EQ(nm.best(), Eigen::VectorXd(Eigen::Vector2d(0, 0)));
  nm.set_weights({0.0, 1.0});
  EXPECT_EQ(nm.best(), Eigen::VectorXd(Eigen::Vector2d(1, 1)));
  EXPECT_EQ(calls, 3);
}

}  // namespace
}  // namespace simcap::tracker::gomez
