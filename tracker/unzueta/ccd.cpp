#include "tracker/unzueta/ccd.h"

#include <cmath>

namespace simcap {
namespace {

// Signed angle from a to b about unit axis n, both taken in the plane normal to n.
double angle_about(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& n) {
  const Eigen::Vector3d pa = a - a.dot(n) * n, pb = b - b.dot(n) * n;
  return std::atan2(pa.cross(pb).dot(n), pa.dot(pb));
}

}  // namespace

CcdSolver::CcdSolver(SikBody body, CcdOptions options, CcdVariant variant)
    : options_(options),
      variant_(variant),
      body_(std::move(body)),
      limits_(body_),
      pelvis_(options.pelvis_weights),
      limbs_(body_, limits_, nullptr, SikSwivel::reference),
      pose_(Pose::neutral(body_.skeleton())),
      spine_(body_.spine().begin() + 1, body_.spine().end()) {
  for (int side : {kLeft, kRight}) {
    const SikLimb& arm = body_.arm(side);
    if (arm.clavicle >= 0) arm_[side].push_back(arm.clavicle);
    arm_[side].insert(arm_[side].end(), {arm.a, arm.b});
    leg_[side] = {body_.leg(side).a, body_.leg(side).b};
  }
}

void CcdSolver::reset() {
  pelvis_.reset();
  pose_ = Pose::neutral(body_.skeleton());
}

void CcdSolver::update_world() {
  body_.forward(pose_, rotation_, position_);
}

void CcdSolver::descend(const std::vector<int>& chain, int effector,
                        const Eigen::Vector3d& target) {
  update_world();
  double error = (position_[effector] - target).norm();
  for (int sweep = 0; sweep < options_.max_iterations && error >= options_.tolerance; ++sweep) {
    // From the joint next to the end-effector back to the chain's base.
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      const int j = *it;
      const Eigen::Vector3d to_effector = position_[effector] - position_[j];
      const Eigen::Vector3d to_target = target - position_[j];
      Eigen::Quaterniond q;
      if (limits_[j].kind == SikLimitKind::hinge) {
        // A 1-DoF joint turns about its own axis only.
        const Eigen::Vector3d& axis = limits_[j].pole;
        q = pose_.rotations[j] *
            Eigen::AngleAxisd(angle_about(to_effector, to_target, rotation_[j] * axis), axis);
      } else {
        const Eigen::Quaterniond& parent = rotation_[body_.parent(j)];
        q = parent.conjugate() * Eigen::Quaterniond::FromTwoVectors(to_effector, to_target) *
            parent * pose_.rotations[j];
      }
      pose_.rotations[j] = (options_.limits ? limits_.clamp(j, q) : q).normalized();
      update_world();
    }
    const double next = (position_[effector] - target).norm();
    const bool stalled = error - next < options_.min_improvement;
    error = next;
    if (stalled) break;
  }
}

const Pose& CcdSolver::solve(const SikTargets& targets) {
  if (variant_ == CcdVariant::kma) pose_ = Pose::neutral(body_.skeleton());
  pose_.rotations[body_.root()] = Eigen::Quaterniond(pelvis_.estimate(targets));
  pose_.root_position = targets.pelvis;
  descend(spine_, body_.head(), targets.head);
  // As for SIK's spine: half of the head's residual is moved to the pelvis.
  pose_.root_position -= 0.5 * (position_[body_.head()] - targets.head);
  if (variant_ == CcdVariant::kma) {
    update_world();
    for (int side : {kLeft, kRight}) {
      limbs_.place_leg(side, targets.ankle[side], std::nullopt, options_.limits, pose_, world_);
      limbs_.place_arm(side, targets.wrist[side], std::nullopt, options_.limits, pose_, world_);
    }
    return pose_;
  }
  for (int side : {kLeft, kRight}) {
    descend(leg_[side], body_.leg(side).c, targets.ankle[side]);
    descend(arm_[side], body_.arm(side).c, targets.wrist[side]);
  }
  return pose_;
}

}  // namespace simcap
