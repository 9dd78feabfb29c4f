// The monocular tracker's pose state: one number per degree of freedom of its articulated body
// (root translation and rotation, Gomez Jauregui's Table 2-1 angles, the legs' angles), with the
// joint-limit box, the partition each belongs to (heuristic H2) and its MPEG-4 BAP id.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/name_table.h"
#include "models/pose.h"
#include "models/skeleton.h"

namespace simcap::tracker::gomez {

// full: the whole body (root free, trunk, neck, arms, legs); upper: the thesis's upper body
// (trunk at vl5, neck, arms, wrists: the 20 angles of Table 2-1), root and legs held at the
// first frame's pose.
enum class BodyKind { full, upper };
inline constexpr NameTable<BodyKind, 2> kBodyKinds{
    {{"full", BodyKind::full}, {"upper", BodyKind::upper}}};

// The partitions of the hierarchical partitioned diffusion (H2): the thesis's chest (whose
// motion moves everything), head, left and right arm, and for the full body the legs.
enum class Part : std::uint8_t { torso, head, left_arm, right_arm, left_leg, right_leg };
inline constexpr int kPartCount = 6;

using State = Eigen::VectorXd;

// A point of the body that may touch the floor (under a heel, a toe), in its joint's frame.
struct FloorContact {
  int joint = 0;
  Eigen::Vector3d point;
};

struct Dof {
  std::string name;  // "root_tx", "l_shoulder_flexion", ... (URDF-style, models/joint_limits.h)
  int joint = -1;    // skeleton joint it rotates (the root for translations)
  int axis = 0;      // 0: X, 1: Y, 2: Z of the joint's world-aligned neutral frame
  bool translation = false;
  double lower = 0, upper = 0;  // box (radians or metres)
  double step = 0;  // typical change from frame to frame at 30 frames/s: diffusion, simplex size
  Part part = Part::torso;
  int bap = 0;  // MPEG-4 BAP id (models/mpeg4_bap.h), 0 when none
};

class BodyDofs {
 public:
  // The DOFs of `kind` on `skeleton` (build_humanoid's joint names; kept by reference). `first`
  // is the first frame's pose: the upper body holds every joint it has no DOF for (root, legs,
  // spine above vl5) there; the full body's joints without DOFs stay neutral, its root may go
  // two full turns either way from first's heading and `reach_m` from first's position.
  // With `floor` contacts the full body stands on the floor y = 0: the root's height is not a
  // DOF but follows from the legs, so that the lowest contact touches the floor.
  BodyDofs(const Skeleton& skeleton, BodyKind kind, const Pose& first,
           std::vector<FloorContact> floor = {}, double reach_m = 10.0);

  BodyKind kind() const { return kind_; }
  int size() const { return static_cast<int>(dofs_.size()); }
  const Dof& operator[](int i) const { return dofs_[i]; }
  const std::vector<Dof>& dofs() const { return dofs_; }
  const Skeleton& skeleton() const { return *skeleton_; }
  // Index of the DOF called `name`; throws Error when absent.
  int require(std::string_view name) const;
  int find(std::string_view name) const;  // -1 when absent
  // DOF indices of a joint, in composition order (R = R(first) R(second) ...).
  const std::vector<int>& joint_dofs(int joint) const { return joint_dofs_[joint]; }
  std::vector<int> part_dofs(Part part) const;

  Pose pose(const State& x) const;
  // The angles of `pose` on this body's DOFs (Tait-Bryan decomposition in each joint's order,
  // the representation within the limits, or nearest `near` when both or neither are); the
  // parts the DOFs do not move are ignored.
  State state_of(const Pose& pose, const State& near) const;
  // The rotation DOFs of one joint from its rotation (as state_of, for that joint only).
  void set_joint(int joint, const Eigen::Quaterniond& rotation, State& x) const;
  State clamp(State x) const;
  bool inside(const State& x, double slack = 1e-9) const;
  State steps() const;
  State lower() const;
  State upper() const;

 private:
  const Skeleton* skeleton_;
  BodyKind kind_;
  Pose fixed_;  // the pose parts without DOFs keep
  std::vector<Dof> dofs_;
  std::vector<std::vector<int>> joint_dofs_;
  std::vector<FloorContact> floor_;
};

}  // namespace simcap::tracker::gomez
