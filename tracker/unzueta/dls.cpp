#include "tracker/unzueta/dls.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;
// PIK's lowest priority, a joint-space cost: the standing pose with elbows and knees bent by
// this much (radians, "slightly bent"), pulled toward by this fraction of the way per iteration.
constexpr double kRelaxedFlexion = 0.3;
constexpr double kRelaxedGain = 0.1;
// PIK's levels: ankles, then wrists, then the head (rows of the 15-row error, 3 per effector in
// the order head, left wrist, right wrist, left ankle, right ankle).
constexpr std::array<int, 5> kPikEffectorOrder = {3, 4, 1, 2, 0};

double wrap(double a) {
  return std::remainder(a, 2 * kPi);
}

Eigen::Quaterniond from_euler(const Eigen::Vector3d& e) {
  return Eigen::AngleAxisd(e.x(), Eigen::Vector3d::UnitX()) *
         Eigen::AngleAxisd(e.y(), Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(e.z(), Eigen::Vector3d::UnitZ());
}

// XYZ follower Euler angles of q (R = Rx Ry Rz), of the two solutions the one nearer `near`,
// each angle unwrapped next to its previous value.
Eigen::Vector3d to_euler(const Eigen::Quaterniond& q, const Eigen::Vector3d& near) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const double b = std::asin(std::clamp(r(0, 2), -1.0, 1.0));
  const Eigen::Vector3d first(std::atan2(-r(1, 2), r(2, 2)), b, std::atan2(-r(0, 1), r(0, 0)));
  const Eigen::Vector3d second(first.x() + kPi, kPi - b, first.z() + kPi);
  auto distance = [&](const Eigen::Vector3d& e) {
    double d = 0.0;
    for (int i = 0; i < 3; ++i) d += std::abs(wrap(e[i] - near[i]));
    return d;
  };
  const Eigen::Vector3d& best = distance(first) <= distance(second) ? first : second;
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) out[i] = near[i] + wrap(best[i] - near[i]);
  return out;
}

}  // namespace

DlsSolver::DlsSolver(SikBody body, DlsOptions options)
    : options_(options),
      body_(std::move(body)),
      limits_(body_),
      pelvis_(options.pelvis_weights),
      pose_(Pose::neutral(body_.skeleton())) {
  ball_joints_.assign(body_.spine().begin() + 1, body_.spine().end());
  for (int side : {kLeft, kRight}) {
    if (body_.arm(side).clavicle >= 0) ball_joints_.push_back(body_.arm(side).clavicle);
    ball_joints_.push_back(body_.arm(side).a);
    ball_joints_.push_back(body_.leg(side).a);
    hinge_joints_.push_back(body_.arm(side).b);
    hinge_joints_.push_back(body_.leg(side).b);
  }
  for (int j : ball_joints_) {
    for (int axis = 0; axis < 3; ++axis) dofs_.push_back({j, axis});
  }
  for (int j : hinge_joints_) dofs_.push_back({j, -1});
  angles_ = Eigen::VectorXd::Zero(static_cast<int>(dofs_.size()));
  relaxed_ = angles_;
  relaxed_.tail(static_cast<int>(hinge_joints_.size())).setConstant(kRelaxedFlexion);
  effector_joint_ = {body_.head(), body_.arm(kLeft).c, body_.arm(kRight).c, body_.leg(kLeft).c,
                     body_.leg(kRight).c};
  for (const Dof& d : dofs_) {
    std::vector<int> moved;
    for (int i = 0; i < 5; ++i) {
      if (body_.skeleton().is_descendant(effector_joint_[i], d.joint)) moved.push_back(i);
    }
    effectors_.push_back(std::move(moved));
  }
}

void DlsSolver::reset() {
  pelvis_.reset();
  angles_.setZero();
  pose_ = Pose::neutral(body_.skeleton());
}

void DlsSolver::pose_from_angles() {
  int k = 0;
  for (int j : ball_joints_) {
    pose_.rotations[j] = from_euler(angles_.segment<3>(k));
    k += 3;
  }
  for (int j : hinge_joints_) {
    pose_.rotations[j] = Eigen::AngleAxisd(angles_[k++], limits_[j].pole);
  }
}

void DlsSolver::place_root(const SikTargets& targets) {
  pose_.root_position = targets.pelvis;
  body_.forward(pose_, rotation_, position_);
  // PIK's root marker has the highest priority: it stays on its target.
  if (options_.update == JacobianUpdate::kPrioritized) return;
  const Eigen::Vector3d shift = -0.5 * (position_[body_.head()] - targets.head);
  pose_.root_position += shift;
  for (Eigen::Vector3d& p : position_) p += shift;
}

double DlsSolver::largest_error(const SikTargets& targets) const {
  const std::array<Eigen::Vector3d, 5> goal = {targets.head, targets.wrist[kLeft],
                                               targets.wrist[kRight], targets.ankle[kLeft],
                                               targets.ankle[kRight]};
  double worst = 0.0;
  for (int i = 0; i < 5; ++i) {
    worst = std::max(worst, (position_[effector_joint_[i]] - goal[i]).norm());
  }
  return worst;
}

bool DlsSolver::clamp_joint(int k, Eigen::VectorXd& angles) const {
  const int j = dofs_[k].joint;
  if (dofs_[k].axis < 0) {
    const double clamped = std::clamp(angles[k], limits_[j].min, limits_[j].max);
    if (clamped == angles[k]) return false;
    angles[k] = clamped;
    return true;
  }
  const Eigen::Vector3d e = angles.segment<3>(k);
  const Eigen::Quaterniond q = from_euler(e);
  if (limits_.excess(j, q) <= 0.0) return false;
  angles.segment<3>(k) = to_euler(limits_.clamp(j, q), e);
  return true;
}

Eigen::VectorXd DlsSolver::pik_step(const Eigen::MatrixXd& jacobian,
                                    const Eigen::VectorXd& residual) const {
  const int n = static_cast<int>(dofs_.size());
  Eigen::MatrixXd j(15, n);
  Eigen::VectorXd e(15);
  for (int level = 0; level < 5; ++level) {
    j.middleRows<3>(3 * level) = jacobian.middleRows<3>(3 * kPikEffectorOrder[level]);
    e.segment<3>(3 * level) = residual.segment<3>(3 * kPikEffectorOrder[level]);
  }
  const std::vector<int> level_rows = {6, 6, 3};
  const Eigen::VectorXd relax = kRelaxedGain * (relaxed_ - angles_);
  std::vector<bool> fixed(n, false);
  Eigen::VectorXd fixed_step = Eigen::VectorXd::Zero(n);
  for (;;) {
    Eigen::MatrixXd free_j = j;
    Eigen::VectorXd free_relax = relax;
    for (int k = 0; k < n; ++k) {
      if (!fixed[k]) continue;
      free_j.col(k).setZero();
      free_relax[k] = 0.0;
    }
    Eigen::VectorXd step =
        prioritized_step(free_j, e - j * fixed_step, level_rows, options_.damping, free_relax);
    for (int k = 0; k < n; ++k) {
      if (fixed[k]) step[k] = fixed_step[k];
    }
    if (!options_.limits) return step;
    Eigen::VectorXd trial = angles_ + step;
    bool added = false;
    for (int k = 0; k < n; k += dofs_[k].axis < 0 ? 1 : 3) {
      if (fixed[k] || !clamp_joint(k, trial)) continue;
      const int size = dofs_[k].axis < 0 ? 1 : 3;
      for (int i = k; i < k + size; ++i) {
        fixed[i] = true;
        fixed_step[i] = trial[i] - angles_[i];
      }
      added = true;
    }
    if (!added) return step;
  }
}

const Pose& DlsSolver::solve(const SikTargets& targets) {
  const std::array<Eigen::Vector3d, 5> goal = {targets.head, targets.wrist[kLeft],
                                               targets.wrist[kRight], targets.ankle[kLeft],
                                               targets.ankle[kRight]};
  pose_.rotations[body_.root()] = Eigen::Quaterniond(pelvis_.estimate(targets));
  pose_from_angles();
  place_root(targets);
  double error = largest_error(targets);
  const int n = static_cast<int>(dofs_.size());
  Eigen::MatrixXd jacobian(15, n);
  Eigen::VectorXd residual(15);
  for (int iteration = 0; iteration < options_.max_iterations && error >= options_.tolerance;
       ++iteration) {
    for (int i = 0; i < 5; ++i)
      residual.segment<3>(3 * i) = goal[i] - position_[effector_joint_[i]];
    jacobian.setZero();
    for (int k = 0; k < n; ++k) {
      const Dof& d = dofs_[k];
      const Eigen::Quaterniond& parent = rotation_[body_.parent(d.joint)];
      Eigen::Vector3d axis;
      if (d.axis < 0) {
        axis = parent * limits_[d.joint].pole;
      } else {
        // Follower axes: X, then Y after the X turn, then Z after both.
        const int first = k - d.axis;
        Eigen::Quaterniond frame = parent;
        if (d.axis >= 1)
          frame = frame * Eigen::AngleAxisd(angles_[first], Eigen::Vector3d::UnitX());
        if (d.axis >= 2)
          frame = frame * Eigen::AngleAxisd(angles_[first + 1], Eigen::Vector3d::UnitY());
        axis = frame * Eigen::Vector3d::Unit(d.axis);
      }
      for (int i : effectors_[k]) {
        jacobian.block<3, 1>(3 * i, k) =
            axis.cross(position_[effector_joint_[i]] - position_[d.joint]);
      }
    }
    angles_ += options_.update == JacobianUpdate::kPrioritized
                   ? pik_step(jacobian, residual)
                   : jacobian_step(options_.update, jacobian, residual, options_.damping);
    if (options_.limits) {
      for (int k = 0; k < n; k += dofs_[k].axis < 0 ? 1 : 3) clamp_joint(k, angles_);
    }
    pose_from_angles();
    place_root(targets);
    const double next = largest_error(targets);
    const bool stalled = error - next < options_.min_improvement;
    error = next;
    if (stalled) break;
  }
  return pose_;
}

}  // namespace simcap
