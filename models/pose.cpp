#include "models/pose.h"

#include "core/error.h"

namespace simcap {

Pose Pose::neutral(const Skeleton& skeleton) {
  Pose p;
  p.root_position = skeleton.size() ? skeleton[0].center : Eigen::Vector3d::Zero();
  p.rotations.assign(skeleton.size(), Eigen::Quaterniond::Identity());
  return p;
}

std::vector<Eigen::Isometry3d> forward_kinematics(const Skeleton& skeleton, const Pose& pose) {
  if (static_cast<int>(pose.rotations.size()) != skeleton.size()) {
    throw Error("pose has " + std::to_string(pose.rotations.size()) + " rotations, skeleton has " +
                std::to_string(skeleton.size()) + " joints");
  }
  std::vector<Eigen::Isometry3d> world(skeleton.size());
  for (int j = 0; j < skeleton.size(); ++j) {
    Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
    local.linear() = pose.rotations[j].normalized().toRotationMatrix();
    const int p = skeleton[j].parent;
    if (p < 0) {
      local.translation() = pose.root_position;
      world[j] = local;
    } else {
      local.translation() = skeleton.offset(j);
      world[j] = world[p] * local;
    }
  }
  return world;
}

std::vector<Eigen::Vector3d> joint_positions(const Skeleton& skeleton, const Pose& pose) {
  const auto world = forward_kinematics(skeleton, pose);
  std::vector<Eigen::Vector3d> out(world.size());
  for (size_t i = 0; i < world.size(); ++i) out[i] = world[i].translation();
  return out;
}

}  // namespace simcap
