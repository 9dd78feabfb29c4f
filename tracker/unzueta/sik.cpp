#include "tracker/unzueta/sik.h"

namespace simcap {

SikSolver::SikSolver(SikBody body, SikOptions options)
    : options_(options),
      body_(std::move(body)),
      limits_(body_),
      pelvis_(options.pelvis_weights),
      spine_(body_, limits_, options.spine_bend),
      limbs_(body_, limits_, nullptr, options.swivel),
      pose_(Pose::neutral(body_.skeleton())) {}

SikSolver::SikSolver(SikBody body, const BodyMesh& mesh, SikOptions options, double floor_y)
    : options_(options),
      body_(std::move(body)),
      limits_(body_),
      collider_(std::in_place, body_, mesh, floor_y),
      pelvis_(options.pelvis_weights),
      spine_(body_, limits_, options.spine_bend),
      limbs_(body_, limits_, &*collider_, options.swivel),
      pose_(Pose::neutral(body_.skeleton())) {}

void SikSolver::reset() {
  pelvis_.reset();
  spine_.reset();
}

const Pose& SikSolver::solve(const SikTargets& targets) {
  std::fill(pose_.rotations.begin(), pose_.rotations.end(), Eigen::Quaterniond::Identity());
  const Eigen::Matrix3d pelvis_frame = targets.pelvis_orientation
                                           ? targets.pelvis_orientation->toRotationMatrix()
                                           : pelvis_.estimate(targets);
  spine_.solve(targets, pelvis_frame, options_.limits, pose_);
  if (targets.head_orientation)
    spine_.twist_to_head(*targets.head_orientation, options_.limits, pose_);
  body_.forward(pose_, world_.rotation, world_.position);
  for (int side : {kLeft, kRight}) {
    limbs_.place_leg(side, targets.ankle[side], targets.knee[side], options_.limits, pose_, world_);
  }
  for (int side : {kLeft, kRight}) {
    limbs_.place_clavicle(side, targets.wrist[side], options_.limits, pose_, world_);
    limbs_.place_arm(side, targets.wrist[side], targets.elbow[side], options_.limits, pose_,
                     world_);
  }
  return pose_;
}

}  // namespace simcap
