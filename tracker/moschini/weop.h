// Weighted extended orthogonal Procrustes (Moschini §4.2, article §2.2): the rotation and
// translation, or the rotation alone (WOPP), that best maps weighted model points onto data.
#pragma once

#include <Eigen/Core>

namespace simcap::tracker {

struct RigidMotion {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

// Article convention: points are the columns of A (model) and B (data), W = diag(w), u = ones;
// minimizes ||(R A + t u^T - B) W||_F^2 with R a rotation. The cost weights point i by w_i^2.
// With all weights zero the identity is returned.
RigidMotion weop(const Eigen::Matrix3Xd& A, const Eigen::Matrix3Xd& B, const Eigen::VectorXd& w);

// The same problem with t = 0 (u = 0 in the article): the rotation about the origin, for a limb
// whose points are expressed relative to its proximal joint so that it stays attached.
Eigen::Matrix3d wopp(const Eigen::Matrix3Xd& A, const Eigen::Matrix3Xd& B,
                     const Eigen::VectorXd& w);

}  // namespace simcap::tracker
