// Analytic inverse kinematics of the arms (shoulder 3 DOFs + elbow flexion) for the particle
// filter's depth heuristics: kinematic flipping (H4, after Sminchisescu & Triggs 2003: the
// elbow and wrist moved to the other intersection of their camera ray with the sphere about
// their parent joint, which keeps their image projection) and the end-effector state (H5: the
// wrist's position plus the elbow's swivel angle about the shoulder-wrist line, Tolani 2000).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "tracker/gomez/body_dofs.h"

namespace simcap::tracker::gomez {

struct ArmPoints {
  Eigen::Vector3d shoulder, elbow, wrist;  // world
  Eigen::Matrix3d parent;                  // world rotation of the shoulder's parent joint
};

// The legs have the arms' structure (the hip a ball joint, the knee a hinge about X): the same
// solver reaches a foot to a camera ray; shoulder/elbow/wrist below read hip/knee/ankle for them.
enum class Limbs { arms, legs };

class ArmKinematics {
 public:
  // The arms (or legs) of `dofs` (l_/r_ shoulder or hip with 3 DOFs, elbow or knee with 1 about
  // X). Keeps a reference.
  explicit ArmKinematics(const BodyDofs& dofs, Limbs limbs = Limbs::arms);

  // side 0: left, 1: right.
  ArmPoints points(const State& x, int side) const;
  double upper_length(int side) const { return upper_[side].norm(); }
  double fore_length(int side) const { return fore_[side].norm(); }

  // Sets the shoulder's and elbow's DOFs of `side` so that the elbow lies at `elbow` and the
  // wrist at `wrist` (world; the distances must be the segments' lengths), the other DOFs
  // unchanged. Returns false, leaving the angles clamped to the box, when the solution lies
  // outside the joint limits or the wrist is out of reach.
  bool solve(State& x, int side, const Eigen::Vector3d& elbow, const Eigen::Vector3d& wrist) const;

  // The elbow on its swivel circle for a wrist at `wrist` (swivel angle measured about the
  // shoulder-to-wrist axis from the trunk's downward direction); empty when out of reach.
  std::optional<Eigen::Vector3d> swivel_elbow(const ArmPoints& arm, const Eigen::Vector3d& wrist,
                                              double swivel) const;
  double swivel(const ArmPoints& arm) const;

  // The poses with the same image projection of both arms' elbows and wrists seen from
  // `camera_centre` (up to 15: each arm's elbow and wrist flipped or not), within the limits.
  std::vector<State> flips(const State& x, const Eigen::Vector3d& camera_centre) const;

  // Poses of `side`'s arm that put its hand point (`hand`, in the wrist joint's frame) on the
  // camera ray `origin + t direction` (unit direction): `depths` depths spread evenly over the
  // stretch of the ray within the arm's reach, each with the elbow at the swivel nearest its
  // present one that the limits allow (none at a depth where no swivel does); the other DOFs
  // unchanged. The ray fixes
  // the hand's image position, not its depth: the image cannot, so every depth is proposed.
  std::vector<State> reach_ray(const State& x, int side, const Eigen::Vector3d& hand,
                               const Eigen::Vector3d& origin, const Eigen::Vector3d& direction,
                               int depths) const;

  // The pose of `side`'s limb that puts its hand point (as for reach_ray) at `target` (world),
  // the elbow at the swivel nearest its present one that the limits allow; none when no swivel
  // does or the target is out of reach.
  std::optional<State> reach_point(const State& x, int side, const Eigen::Vector3d& hand,
                                   const Eigen::Vector3d& target) const;

 private:
  // solve() for the point `end` at offset `f0` in the elbow's frame instead of the wrist.
  bool solve_end(State& x, int side, const Eigen::Vector3d& elbow, const Eigen::Vector3d& end,
                 const Eigen::Vector3d& f0) const;
  // swivel_elbow() for an end point at distance `L2` from the elbow.
  std::optional<Eigen::Vector3d> swivel_elbow(const ArmPoints& arm, const Eigen::Vector3d& end,
                                              double swivel, double L2) const;

  const BodyDofs* dofs_;
  int shoulder_[2], elbow_[2], wrist_[2];
  int elbow_dof_[2];
  Eigen::Vector3d upper_[2], fore_[2];  // neutral offsets: shoulder -> elbow, elbow -> wrist
};

}  // namespace simcap::tracker::gomez
