#include "tracker/moschini/weop.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/error.h"

namespace simcap::tracker {
namespace {

void check_sizes(const Eigen::Matrix3Xd& A, const Eigen::Matrix3Xd& B, const Eigen::VectorXd& w) {
  if (A.cols() != B.cols() || A.cols() != w.size()) {
    throw Error("weop: A, B and w must hold the same number of points");
  }
}

// R = V diag(1, 1, det(V U^T)) U^T for U D V^T = M: the closest rotation, never a reflection.
Eigen::Matrix3d rotation_from(const Eigen::Matrix3d& M) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d& U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  Eigen::Vector3d d(1.0, 1.0, (V * U.transpose()).determinant() < 0 ? -1.0 : 1.0);
  return V * d.asDiagonal() * U.transpose();
}

}  // namespace

RigidMotion weop(const Eigen::Matrix3Xd& A, const Eigen::Matrix3Xd& B, const Eigen::VectorXd& w) {
  check_sizes(A, B, w);
  // A_w (I - u_w u_w^T / u_w^T u_w) B_w^T with u_w = W u = w expands to the weighted
  // cross-covariance about the weighted centroids, which avoids forming the p x p matrix.
  const Eigen::VectorXd w2 = w.array().square();
  const double total = w2.sum();
  RigidMotion motion;
  if (!(total > 0)) return motion;
  const Eigen::Vector3d ca = A * w2 / total;
  const Eigen::Vector3d cb = B * w2 / total;
  const Eigen::Matrix3d M = (A.colwise() - ca) * w2.asDiagonal() * (B.colwise() - cb).transpose();
  motion.R = rotation_from(M);
  motion.t = cb - motion.R * ca;
  return motion;
}

Eigen::Matrix3d wopp(const Eigen::Matrix3Xd& A, const Eigen::Matrix3Xd& B,
                     const Eigen::VectorXd& w) {
  check_sizes(A, B, w);
  const Eigen::VectorXd w2 = w.array().square();
  if (!(w2.sum() > 0)) return Eigen::Matrix3d::Identity();
  return rotation_from(A * w2.asDiagonal() * B.transpose());
}

}  // namespace simcap::tracker
