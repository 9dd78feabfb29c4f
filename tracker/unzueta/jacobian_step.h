// The joint-angle updates of the Jacobian baselines of Unzueta's Table 10: pseudoinverse, damped
// least squares (by normal equations or by SVD), selectively damped least squares and priorities.
#pragma once

#include <Eigen/Core>
#include <string_view>
#include <vector>

namespace simcap {

enum class JacobianUpdate {
  kPseudoinverse,  // Whitney 1969: dq = J^+ e
  kDls,            // Nakamura & Hanafusa 1986, Wampler 1986: dq = J^T (J J^T + lambda^2 I)^-1 e
  kDlsSvd,         // Maciejewski 1990: the same damping, sum of s/(s^2 + lambda^2) (u.e) v
  kSdls,           // Buss & Kim 2005: each singular direction damped by its own step bound
  kPrioritized,    // Baerlocher & Boulic 2004: each task in the null space of the ones above
};

// "pinv", "dls", "dls-svd", "sdls" or "pik".
std::string_view jacobian_update_name(JacobianUpdate update);

// The joint step for the error `e` (3 rows per end-effector) and the Jacobian `j` (one column per
// joint degree of freedom, rows as `e`). `damping` is lambda (a length; kDls and kDlsSvd only).
// Singular values below 1e-9 of the largest are treated as zero.
Eigen::VectorXd jacobian_step(JacobianUpdate update, const Eigen::MatrixXd& j,
                              const Eigen::VectorXd& e, double damping);

// J^T (J J^T + damping^2 I)^-1 by SVD; damping 0 gives Whitney's J^+. Singular values below
// 1e-9 of the largest, or of `scale` when that is larger, are treated as zero (a task projected
// into a null space it barely reaches must not be inverted relative to its own tiny size).
Eigen::MatrixXd damped_pseudoinverse(const Eigen::MatrixXd& j, double damping, double scale = 0.0);

// Baerlocher & Boulic's task-priority step. The rows of `j` and `e` hold the tasks in
// `level_rows` consecutive rows each, highest priority first. Level k is solved by the damped
// pseudoinverse of J_k N_(k-1) for what the levels above leave of its error, N_k = N_(k-1) -
// (J_k N_(k-1))^+ (J_k N_(k-1)) with the exact pseudoinverse, so a level never changes J_i dq of a
// level i above it; `joint_step` (a joint-space descent, one entry per column) is projected into
// the null space of all levels.
Eigen::VectorXd prioritized_step(const Eigen::MatrixXd& j, const Eigen::VectorXd& e,
                                 const std::vector<int>& level_rows, double damping,
                                 const Eigen::VectorXd& joint_step);

// Buss & Kim's SDLS step on its own: per singular direction i, the step (u_i.e / s_i) v_i is
// clamped (largest component) to gamma_i = min(1, N_i / M_i) gamma_max, where N_i sums the
// per-end-effector norms of u_i and M_i = sum over end-effectors l and joints k of
// |v_ki| |J_lk| / s_i says how far that direction moves the end-effectors; the sum is clamped to
// gamma_max (radians, their pi/4).
Eigen::VectorXd sdls_step(const Eigen::MatrixXd& j, const Eigen::VectorXd& e, double gamma_max);

}  // namespace simcap
