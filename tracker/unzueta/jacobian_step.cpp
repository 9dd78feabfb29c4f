#include "tracker/unzueta/jacobian_step.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <numbers>

namespace simcap {
namespace {

constexpr double kRelativeZero = 1e-9;

// Scales v down so that its largest component is at most `bound` in magnitude.
Eigen::VectorXd clamp_max_abs(const Eigen::VectorXd& v, double bound) {
  const double largest = v.cwiseAbs().maxCoeff();
  return largest > bound ? Eigen::VectorXd(v * (bound / largest)) : v;
}

}  // namespace

std::string_view jacobian_update_name(JacobianUpdate update) {
  switch (update) {
    case JacobianUpdate::kPseudoinverse:
      return "pinv";
    case JacobianUpdate::kDls:
      return "dls";
    case JacobianUpdate::kDlsSvd:
      return "dls-svd";
    case JacobianUpdate::kSdls:
      return "sdls";
  }
  return "dls";
}

Eigen::VectorXd sdls_step(const Eigen::MatrixXd& j, const Eigen::VectorXd& e, double gamma_max) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::MatrixXd& u = svd.matrixU();
  const Eigen::MatrixXd& v = svd.matrixV();
  const int effectors = static_cast<int>(j.rows()) / 3;
  // rho(k): sum over end-effectors of |J_lk|, how far joint k moves all of them per radian.
  Eigen::VectorXd rho = Eigen::VectorXd::Zero(j.cols());
  for (int k = 0; k < j.cols(); ++k) {
    for (int l = 0; l < effectors; ++l) rho[k] += j.block<3, 1>(3 * l, k).norm();
  }
  Eigen::VectorXd step = Eigen::VectorXd::Zero(j.cols());
  for (int i = 0; i < s.size(); ++i) {
    if (s[i] <= kRelativeZero * s[0]) break;
    const double alpha = u.col(i).dot(e);
    double n = 0.0;
    for (int l = 0; l < effectors; ++l) n += u.block<3, 1>(3 * l, i).norm();
    const double m = v.col(i).cwiseAbs().dot(rho) / s[i];
    const double gamma = std::min(1.0, n / m) * gamma_max;
    step += clamp_max_abs(v.col(i) * (alpha / s[i]), gamma);
  }
  return clamp_max_abs(step, gamma_max);
}

Eigen::VectorXd jacobian_step(JacobianUpdate update, const Eigen::MatrixXd& j,
                              const Eigen::VectorXd& e, double damping) {
  if (update == JacobianUpdate::kDls) {
    Eigen::MatrixXd normal = j * j.transpose();
    normal.diagonal().array() += damping * damping;
    return j.transpose() * normal.ldlt().solve(e);
  }
  if (update == JacobianUpdate::kSdls) return sdls_step(j, e, std::numbers::pi / 4);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::VectorXd step = Eigen::VectorXd::Zero(j.cols());
  for (int i = 0; i < s.size(); ++i) {
    if (s[i] <= kRelativeZero * s[0]) break;
    const double gain = update == JacobianUpdate::kPseudoinverse
                            ? 1.0 / s[i]
                            : s[i] / (s[i] * s[i] + damping * damping);
    step += svd.matrixV().col(i) * (gain * svd.matrixU().col(i).dot(e));
  }
  return step;
}

}  // namespace simcap
