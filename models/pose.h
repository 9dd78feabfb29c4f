// A pose of a Skeleton (root position plus one rotation per joint, relative to the neutral
// pose) and its forward kinematics: the world transform of every joint and site.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "models/skeleton.h"

namespace simcap {

struct Pose {
  Eigen::Vector3d root_position = Eigen::Vector3d::Zero();  // world position of joint 0
  // rotations[j]: rotation of joint j relative to the neutral pose, expressed in the parent's
  // frame (which is world-aligned in the neutral pose). Sites keep the identity.
  std::vector<Eigen::Quaterniond> rotations;

  // The neutral pose: every rotation the identity, root at its neutral centre.
  static Pose neutral(const Skeleton& skeleton);
};

// World transforms of all joints: G_root = T(root_position) R_root and
// G_j = G_parent T(offset_j) R_j. The translation part of G_j is the joint's world position.
std::vector<Eigen::Isometry3d> forward_kinematics(const Skeleton& skeleton, const Pose& pose);

// World positions only (the translations of forward_kinematics).
std::vector<Eigen::Vector3d> joint_positions(const Skeleton& skeleton, const Pose& pose);

}  // namespace simcap
