#include "tracker/unzueta/jacobian_step.h"

#include <Eigen/Cholesky>
#include <Eigen/SVD>
#include <algorithm>
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
    case JacobianUpdate::kPrioritized:
      return "pik";
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
  return damped_pseudoinverse(j, update == JacobianUpdate::kPseudoinverse ? 0.0 : damping) * e;
}

Eigen::MatrixXd damped_pseudoinverse(const Eigen::MatrixXd& j, double damping, double scale) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(j, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  Eigen::VectorXd gain = Eigen::VectorXd::Zero(s.size());
  const double zero = kRelativeZero * std::max(s.size() > 0 ? s[0] : 0.0, scale);
  for (int i = 0; i < s.size(); ++i) {
    if (s[i] <= zero) break;
    gain[i] = s[i] / (s[i] * s[i] + damping * damping);
  }
  return svd.matrixV() * gain.asDiagonal() * svd.matrixU().transpose();
}

Eigen::VectorXd prioritized_step(const Eigen::MatrixXd& j, const Eigen::VectorXd& e,
                                 const std::vector<int>& level_rows, double damping,
                                 const Eigen::VectorXd& joint_step) {
  const Eigen::Index n = j.cols();
  Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
  Eigen::MatrixXd null_space = Eigen::MatrixXd::Identity(n, n);
  Eigen::Index row = 0;
  for (int rows : level_rows) {
    const auto jk = j.middleRows(row, rows);
    const Eigen::MatrixXd projected = jk * null_space;
    const double scale = jk.norm();
    step += damped_pseudoinverse(projected, damping, scale) * (e.segment(row, rows) - jk * step);
    null_space -= damped_pseudoinverse(projected, 0.0, scale) * projected;
    row += rows;
  }
  return step + null_space * joint_step;
}

}  // namespace simcap
