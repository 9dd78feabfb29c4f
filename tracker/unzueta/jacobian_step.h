// The joint-angle updates of the Jacobian baselines of Unzueta's Table 10: pseudoinverse, damped
// least squares (by normal equations or by SVD) and selectively damped least squares.
#pragma once

#include <Eigen/Core>
#include <string_view>

namespace simcap {

enum class JacobianUpdate {
  kPseudoinverse,  // Whitney 1969: dq = J^+ e
  kDls,            // Nakamura & Hanafusa 1986, Wampler 1986: dq = J^T (J J^T + lambda^2 I)^-1 e
  kDlsSvd,         // Maciejewski 1990: the same damping, sum of s/(s^2 + lambda^2) (u.e) v
  kSdls,           // Buss & Kim 2005: each singular direction damped by its own step bound
};

// "pinv", "dls", "dls-svd" or "sdls".
std::string_view jacobian_update_name(JacobianUpdate update);

// The joint step for the error `e` (3 rows per end-effector) and the Jacobian `j` (one column per
// joint degree of freedom, rows as `e`). `damping` is lambda (a length; kDls and kDlsSvd only).
// Singular values below 1e-9 of the largest are treated as zero.
Eigen::VectorXd jacobian_step(JacobianUpdate update, const Eigen::MatrixXd& j,
                              const Eigen::VectorXd& e, double damping);

// Buss & Kim's SDLS step on its own: per singular direction i, the step (u_i.e / s_i) v_i is
// clamped (largest component) to gamma_i = min(1, N_i / M_i) gamma_max, where N_i sums the
// per-end-effector norms of u_i and M_i = sum over end-effectors l and joints k of
// |v_ki| |J_lk| / s_i says how far that direction moves the end-effectors; the sum is clamped to
// gamma_max (radians, their pi/4).
Eigen::VectorXd sdls_step(const Eigen::MatrixXd& j, const Eigen::VectorXd& e, double gamma_max);

}  // namespace simcap
