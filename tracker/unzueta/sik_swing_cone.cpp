#include "tracker/unzueta/sik_swing_cone.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace simcap {

SwingCone::SwingCone(std::vector<std::pair<double, double>> points) {
  constexpr double pi = std::numbers::pi;
  const int n = static_cast<int>(points.size());
  if (n < 3) throw Error("swing cone: needs at least 3 (theta, psi) points");
  if (std::abs(points.front().first + pi) > 1e-9 || std::abs(points.back().first - pi) > 1e-9) {
    throw Error("swing cone: theta must run from -pi to +pi");
  }
  if (std::abs(points.front().second - points.back().second) > 1e-9) {
    throw Error("swing cone: psi at -pi and +pi must be equal");
  }
  for (int i = 0; i < n; ++i) {
    if (i > 0 && !(points[i].first > points[i - 1].first)) {
      throw Error("swing cone: theta must increase strictly");
    }
    if (!(points[i].second > 0.0 && points[i].second < pi)) {
      throw Error("swing cone: psi must lie in (0, pi)");
    }
    theta_.push_back(points[i].first);
    psi_.push_back(points[i].second);
  }
  // Clamped cubic spline whose end slopes are both the mean of the first and last secants (the
  // thesis' eq. 10), solved for the knot second derivatives.
  std::vector<double> h(n - 1), secant(n - 1);
  for (int i = 0; i + 1 < n; ++i) {
    h[i] = theta_[i + 1] - theta_[i];
    secant[i] = (psi_[i + 1] - psi_[i]) / h[i];
  }
  const double end_slope = 0.5 * (secant.front() + secant.back());
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd b(n);
  a(0, 0) = 2 * h[0];
  a(0, 1) = h[0];
  b(0) = 6 * (secant[0] - end_slope);
  for (int i = 1; i + 1 < n; ++i) {
    a(i, i - 1) = h[i - 1];
    a(i, i) = 2 * (h[i - 1] + h[i]);
    a(i, i + 1) = h[i];
    b(i) = 6 * (secant[i] - secant[i - 1]);
  }
  a(n - 1, n - 2) = h[n - 2];
  a(n - 1, n - 1) = 2 * h[n - 2];
  b(n - 1) = 6 * (end_slope - secant[n - 2]);
  const Eigen::VectorXd m = a.partialPivLu().solve(b);
  second_.assign(m.data(), m.data() + n);
}

double SwingCone::max_swing(double theta) const {
  constexpr double two_pi = 2 * std::numbers::pi;
  theta = theta - two_pi * std::floor((theta + std::numbers::pi) / two_pi);
  const auto it = std::upper_bound(theta_.begin(), theta_.end(), theta);
  const int i =
      std::clamp(static_cast<int>(it - theta_.begin()) - 1, 0, static_cast<int>(theta_.size()) - 2);
  const double h = theta_[i + 1] - theta_[i];
  const double t1 = (theta_[i + 1] - theta) / h, t0 = (theta - theta_[i]) / h;
  return t1 * psi_[i] + t0 * psi_[i + 1] +
         ((t1 * t1 * t1 - t1) * second_[i] + (t0 * t0 * t0 - t0) * second_[i + 1]) * h * h / 6.0;
}

}  // namespace simcap
