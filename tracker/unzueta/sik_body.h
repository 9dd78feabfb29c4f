// The joints that Sequential Inverse Kinematics and its CCD and DLS baselines drive on an H-Anim
// skeleton (spine chain, clavicles, two-bone limbs) and the six end-effector targets they read.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

#include "models/pose.h"
#include "models/skeleton.h"

namespace simcap {

inline constexpr int kLeft = 0, kRight = 1;

// Unzueta's input (thesis Alg. 7): positions of the pelvis (humanoid_root), head (skullbase),
// wrists (radiocarpal) and ankles (talocrural), world frame, metres. Index sides by kLeft/kRight.
struct SikTargets {
  Eigen::Vector3d pelvis = Eigen::Vector3d::Zero();
  Eigen::Vector3d head = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, 2> wrist{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::array<Eigen::Vector3d, 2> ankle{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // World orientations of humanoid_root and skullbase when measured (thesis Alg. 10-11): the
  // pelvis then replaces the estimate of §4.2 and the spine is twisted to the head's.
  std::optional<Eigen::Quaterniond> pelvis_orientation, head_orientation;
  // Elbow and knee centres when measured (the optional middle targets; the thesis tracks
  // none): the limb then swivels about its root-to-end line until the middle joint lies in the
  // plane of the root, the end and this point, on its side. The end target keeps priority.
  std::array<std::optional<Eigen::Vector3d>, 2> elbow, knee;
};

// A two-bone limb A-B-C (shoulder-elbow-wrist or hip-knee-ankle).
struct SikLimb {
  int a = -1, b = -1, c = -1;
  int clavicle = -1;  // the sternoclavicular joint above an arm's shoulder; -1 for legs or none
  // The anatomical flexion axis of B: perpendicular to the upper segment AB and to the body's
  // front (+Z) in the neutral pose, signed so that a positive turn is flexion (forearm forward,
  // calf back). SIK swings A about it to place B off the line to the target (Alg. 13 line 4).
  Eigen::Vector3d swivel_axis = Eigen::Vector3d::UnitX();
  // B's own flexion axis in its neutral frame, perpendicular to the lower segment BC, same sign
  // convention. By default the anatomical one (perpendicular to BC and the front).
  Eigen::Vector3d hinge_axis = Eigen::Vector3d::UnitX();
};

// Elbow and knee flexion axes of a particular skeleton (neutral frames), when known: a BVH file
// states joint frames but not the axis a hinge turns about (CMU's elbows turn about an axis 30
// degrees off the mediolateral one). Unset entries keep the anatomical default.
struct SikHingeAxes {
  std::array<std::optional<Eigen::Vector3d>, 2> elbow, knee;
};

class SikBody {
 public:
  // Finds the roles by H-Anim name: humanoid_root (joint 0), skullbase, l/r_shoulder, _elbow,
  // _radiocarpal, _hip, _knee, _talocrural, and l/r_sternoclavicular when present. The spine is
  // the path from humanoid_root to skullbase. Throws Error naming a missing or misplaced joint, or
  // a hinge axis along its bone.
  explicit SikBody(Skeleton skeleton, const SikHingeAxes& hinges = {});

  const Skeleton& skeleton() const { return skeleton_; }
  int size() const { return skeleton_.size(); }
  int parent(int j) const { return parent_[j]; }
  const Eigen::Vector3d& offset(int j) const { return offset_[j]; }

  int root() const { return 0; }
  int head() const { return head_; }
  // humanoid_root first, then every joint on the way to skullbase (skullbase excluded).
  const std::vector<int>& spine() const { return spine_; }
  const SikLimb& arm(int side) const { return arm_[side]; }
  const SikLimb& leg(int side) const { return leg_[side]; }
  // Unit direction, in the neutral pose, from joint j to the next distinct joint centre along the
  // chain it drives (spine, clavicle, limb); zero for joints outside the chains.
  const Eigen::Vector3d& segment_direction(int j) const { return segment_[j]; }

  // World rotations and positions of all joints for `pose` (vectors are resized as needed).
  void forward(const Pose& pose, std::vector<Eigen::Quaterniond>& rotation,
               std::vector<Eigen::Vector3d>& position) const;
  // The end-effector targets read off this skeleton's world joint positions.
  SikTargets targets(const std::vector<Eigen::Vector3d>& position) const;

 private:
  Skeleton skeleton_;
  std::vector<int> parent_;
  std::vector<Eigen::Vector3d> offset_;
  std::vector<Eigen::Vector3d> segment_;
  int head_ = -1;
  std::vector<int> spine_;
  std::array<SikLimb, 2> arm_, leg_;
};

}  // namespace simcap
