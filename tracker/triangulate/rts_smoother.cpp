#include "tracker/triangulate/rts_smoother.h"

#include <Eigen/Dense>
#include <cmath>

namespace simcap::tracker {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

// Velocity variance before any frame says anything about it: (10 m/s)².
constexpr double kVelocityPrior = 100.0;

// The filter, and with `backward` the smoother pass too (the likelihood needs only the filter).
SmoothedTrack run(const std::vector<std::optional<PointMeasurement>>& z, double dt, double q,
                  bool backward) {
  SmoothedTrack out;
  out.acceleration_psd = q;
  const size_t n = z.size();
  size_t first = 0;
  while (first < n && !z[first]) ++first;
  if (first == n) return out;

  Matrix6 f = Matrix6::Identity();
  f.topRightCorner<3, 3>() = dt * Eigen::Matrix3d::Identity();
  Matrix6 noise;
  const Eigen::Matrix3d i3 = Eigen::Matrix3d::Identity();
  noise << q * dt * dt * dt / 3 * i3, q * dt * dt / 2 * i3, q * dt * dt / 2 * i3, q * dt * i3;

  // Forward: the filter from the first measurement on, then the frames before it predicted
  // backwards by the smoother pass (they are the same state run back at constant velocity).
  std::vector<Vector6> predicted(n), filtered(n);
  std::vector<Matrix6> predicted_cov(n), filtered_cov(n);
  Vector6 x = Vector6::Zero();
  x.head<3>() = z[first]->position;
  Matrix6 p = Matrix6::Zero();
  p.topLeftCorner<3, 3>() = z[first]->covariance;
  p.bottomRightCorner<3, 3>() = kVelocityPrior * i3;
  predicted[first] = x;
  predicted_cov[first] = p;
  filtered[first] = x;
  filtered_cov[first] = p;
  for (size_t k = first + 1; k < n; ++k) {
    x = f * x;
    p = f * p * f.transpose() + noise;
    predicted[k] = x;
    predicted_cov[k] = p;
    if (z[k]) {
      const Eigen::Vector3d innovation = z[k]->position - x.head<3>();
      const Eigen::Matrix3d s = p.topLeftCorner<3, 3>() + z[k]->covariance;
      const Eigen::LLT<Eigen::Matrix3d> llt(s);
      const Eigen::Matrix<double, 6, 3> gain = llt.solve(p.leftCols<3>().transpose()).transpose();
      x += gain * innovation;
      p -= gain * p.topRows<3>();
      p = 0.5 * (p + p.transpose()).eval();
      const Eigen::Matrix3d l = llt.matrixL();
      out.log_likelihood -=
          0.5 * innovation.dot(llt.solve(innovation)) + l.diagonal().array().log().sum();
    }
    filtered[k] = x;
    filtered_cov[k] = p;
  }
  if (!backward) return out;
  // Backward (Rauch–Tung–Striebel).
  std::vector<Vector6> smoothed(n);
  std::vector<Matrix6> smoothed_cov(n);
  smoothed[n - 1] = filtered[n - 1];
  smoothed_cov[n - 1] = filtered_cov[n - 1];
  for (size_t k = n - 1; k-- > first;) {
    const Matrix6 c = filtered_cov[k] * f.transpose() * predicted_cov[k + 1].inverse();
    smoothed[k] = filtered[k] + c * (smoothed[k + 1] - predicted[k + 1]);
    smoothed_cov[k] =
        filtered_cov[k] + c * (smoothed_cov[k + 1] - predicted_cov[k + 1]) * c.transpose();
  }
  const Matrix6 back = f.inverse();
  for (size_t k = first; k-- > 0;) {
    smoothed[k] = back * smoothed[k + 1];
    smoothed_cov[k] = back * (smoothed_cov[k + 1] + noise) * back.transpose();
  }
  out.points.resize(n);
  for (size_t k = 0; k < n; ++k) {
    out.points[k].position = smoothed[k].head<3>();
    out.points[k].covariance = smoothed_cov[k].topLeftCorner<3, 3>();
  }
  return out;
}

}  // namespace

SmoothedTrack rts_smooth(const std::vector<std::optional<PointMeasurement>>& z, double dt,
                         double q) {
  return run(z, dt, q, true);
}

SmoothedTrack rts_smooth_ml(const std::vector<std::optional<PointMeasurement>>& z, double dt) {
  const auto likelihood = [&](double log_q) {
    return run(z, dt, std::exp(log_q), false).log_likelihood;
  };
  const double step = std::log(2.0);
  const double lo = std::log(1e-3), hi = std::log(1e4);
  double best = lo, best_value = likelihood(lo);
  for (double t = lo + step; t <= hi + 1e-9; t += step) {
    const double v = likelihood(t);
    if (v > best_value) {
      best = t;
      best_value = v;
    }
  }
  // Golden section on [best − step, best + step].
  const double ratio = 0.5 * (std::sqrt(5.0) - 1);
  double a = best - step, b = best + step;
  double c = b - ratio * (b - a), d = a + ratio * (b - a);
  double fc = likelihood(c), fd = likelihood(d);
  for (int i = 0; i < 12; ++i) {
    if (fc > fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - ratio * (b - a);
      fc = likelihood(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + ratio * (b - a);
      fd = likelihood(d);
    }
  }
  const double chosen = fc > fd ? c : d;
  return rts_smooth(z, dt, std::exp(std::max(fc, fd) >= best_value ? chosen : best));
}

}  // namespace simcap::tracker
