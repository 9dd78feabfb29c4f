#include "tracker/unzueta/gesture_normalization.h"

#include <Eigen/LU>
#include <cmath>

#include "core/error.h"

namespace simcap::tracker {

Eigen::MatrixXd resample_clamped_spline(const Eigen::MatrixXd& y, int count) {
  const Eigen::Index k = y.rows();
  if (k < 2 || count < 2) throw Error("spline resampling needs at least 2 samples and 2 states");
  // Second derivatives M at the knots (unit spacing): the clamped end conditions
  // 2 M0 + M1 = 6 ((y1 - y0) - d0) and M(k-2) + 2 M(k-1) = 6 (d1 - (y(k-1) - y(k-2))) vanish for
  // eq. 14's end slopes; inside, M(i-1) + 4 Mi + M(i+1) = 6 (y(i+1) - 2 yi + y(i-1)).
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(k, k);
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(k, y.cols());
  a(0, 0) = 2;
  a(0, 1) = 1;
  a(k - 1, k - 1) = 2;
  a(k - 1, k - 2) = 1;
  for (Eigen::Index i = 1; i + 1 < k; ++i) {
    a(i, i - 1) = 1;
    a(i, i) = 4;
    a(i, i + 1) = 1;
    b.row(i) = 6 * (y.row(i + 1) - 2 * y.row(i) + y.row(i - 1));
  }
  const Eigen::MatrixXd m = a.partialPivLu().solve(b);
  Eigen::MatrixXd out(count, y.cols());
  for (int s = 0; s < count; ++s) {
    const double t = static_cast<double>(s) * static_cast<double>(k - 1) / (count - 1);
    const Eigen::Index i = std::min<Eigen::Index>(static_cast<Eigen::Index>(t), k - 2);
    const double u = t - static_cast<double>(i), w = 1.0 - u;
    out.row(s) = m.row(i) * (w * w * w / 6) + m.row(i + 1) * (u * u * u / 6) +
                 (y.row(i) - m.row(i) / 6) * w + (y.row(i + 1) - m.row(i + 1) / 6) * u;
  }
  return out;
}

Eigen::VectorXd normalize_gesture(const std::vector<Eigen::Vector3d>& path, int states,
                                  double size) {
  Eigen::MatrixXd y(static_cast<Eigen::Index>(path.size()), 3);
  for (size_t i = 0; i < path.size(); ++i) y.row(static_cast<Eigen::Index>(i)) = path[i];
  Eigen::MatrixXd r = resample_clamped_spline(y, states);
  r.rowwise() -= r.colwise().minCoeff();
  const double range = r.maxCoeff();
  if (range > 0) r *= size / range;
  Eigen::MatrixXd rt = r.transpose();  // (x0, y0, z0, x1, ...)
  return Eigen::Map<const Eigen::VectorXd>(rt.data(), rt.size());
}

}  // namespace simcap::tracker
