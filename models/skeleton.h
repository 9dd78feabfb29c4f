// An articulated skeleton in the H-Anim sense: named joints (and end sites) with their centres
// in the neutral pose, parents before children. Joint frames are aligned with the world frame
// in the neutral pose (H-Anim convention), so a pose is just one rotation per joint.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace simcap {

struct Joint {
  std::string name;        // H-Anim joint name (humanoid_root, l_knee, ...) or site name
  std::string segment;     // H-Anim segment that this joint moves (l_calf, ...); empty for sites
  int parent = -1;         // index into the skeleton; -1 for the root only
  Eigen::Vector3d center;  // position in the neutral pose, world frame, metres
  bool is_site = false;    // end site (head top, hand tip, toe tip): a point, never rotated
};

class Skeleton {
 public:
  // Appends a joint; its parent must already be in the skeleton (or -1 for the first joint).
  // Returns its index. Throws Error on a duplicate name or a bad parent.
  int add(Joint joint);

  int size() const { return static_cast<int>(joints_.size()); }
  const Joint& operator[](int i) const { return joints_[i]; }
  const std::vector<Joint>& joints() const { return joints_; }

  // Index of the joint called `name`, or -1.
  int find(std::string_view name) const;
  // Index of the joint called `name`; throws Error naming it when absent.
  int require(std::string_view name) const;
  // Neutral-pose vector from the parent's centre to this joint's centre (zero for the root).
  Eigen::Vector3d offset(int i) const;
  std::vector<int> children(int i) const;
  // True when `descendant` is `ancestor` or lies below it in the tree.
  bool is_descendant(int descendant, int ancestor) const;

 private:
  std::vector<Joint> joints_;
};

}  // namespace simcap
