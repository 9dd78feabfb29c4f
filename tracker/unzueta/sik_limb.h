// SIK's analytic placement of clavicles (Unzueta 2009 Alg. 12) and two-bone limbs (Alg. 13) from
// the neutral stretched limb, with joint limits and the torso and floor collision responses.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <vector>

#include "models/pose.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_collision.h"
#include "tracker/unzueta/sik_limits.h"

namespace simcap {

// World rotations and positions of a body's joints, kept up to date while SIK places parts.
struct SikWorld {
  std::vector<Eigen::Quaterniond> rotation;
  std::vector<Eigen::Vector3d> position;
};

// How a limb without a middle target chooses its swivel about the root-to-end line.
enum class SikSwivel {
  neutral,         // SIK (Alg. 13): whatever the turn from the neutral stretched limb gives
  least_rotation,  // TGBSIK (§4.7.1): the global minimum of swing^2 + twist^2 of A over a turn
  // KMA's TGB zero swivel (§4.7.1): the elbow toward the pelvis' -Y (-Z when in line with the
  // arm), the knee toward its +Z (+Y when in line)
  reference,
};

class SikLimbSolver {
 public:
  // `body`, `limits` and `collider` (nullptr: no collision avoidance) must outlive the solver.
  SikLimbSolver(const SikBody& body, const SikLimits& limits, const SikCollider* collider,
                SikSwivel swivel = SikSwivel::neutral);

  // Alg. 12: if the stretched arm cannot reach `wrist_target`, turns the clavicle (from its
  // neutral orientation) just enough toward it. Needs world entries up to the clavicle's parent.
  void place_clavicle(int side, const Eigen::Vector3d& wrist_target, bool limits, Pose& pose,
                      SikWorld& world) const;
  // Alg. 13 for an arm or a leg, starting from the neutral stretched limb: the end joint on the
  // target when it is reachable within the limits, otherwise as near as the method gets. Needs
  // world entries of every joint above the limb; updates those of A, B and C. With collisions, a
  // leg's ankle is also turned to keep the foot level (see place_limb). With a `middle` target
  // (elbow or knee) the limb then swivels toward it (follow_middle).
  void place_arm(int side, const Eigen::Vector3d& target,
                 const std::optional<Eigen::Vector3d>& middle, bool limits, Pose& pose,
                 SikWorld& world) const;
  void place_leg(int side, const Eigen::Vector3d& target,
                 const std::optional<Eigen::Vector3d>& middle, bool limits, Pose& pose,
                 SikWorld& world) const;

 private:
  // A limb's neutral geometry in its A frame (world-aligned in the neutral pose).
  struct Geometry {
    Eigen::Vector3d ab, bc, hinge, swivel;
    double length_ab = 0, length_bc = 0;
    // |AC(phi)|^2 = c0 + 2 m cos(phi + delta), phi the flexion about the hinge.
    double c0 = 0, m = 0, delta = 0;
  };
  Geometry geometry(const SikLimb& limb) const;
  void place_limb(const SikLimb& limb, const Geometry& g, int side, bool is_arm,
                  const Eigen::Vector3d& target, const std::optional<Eigen::Vector3d>& middle,
                  bool limits, Pose& pose, SikWorld& world) const;
  // Turns A about the line from A to C (C stays put) by `swivel` radians; with limits, only the
  // largest share of it that keeps A within them. Returns the angle turned.
  double swivel_within_limits(const SikLimb& limb, double swivel, bool limits, Pose& pose,
                              SikWorld& world) const;
  // The thesis' use of a known B (§4.4): swivels so that B lies in the half-plane from the A-C
  // line through `middle`.
  void follow_middle(const SikLimb& limb, const Eigen::Vector3d& middle, bool limits, Pose& pose,
                     SikWorld& world) const;
  void least_rotation_swivel(const SikLimb& limb, bool limits, Pose& pose, SikWorld& world) const;
  // follow_middle with a middle target, else the solver's SikSwivel rule.
  void choose_swivel(const SikLimb& limb, bool is_arm, const std::optional<Eigen::Vector3d>& middle,
                     bool limits, Pose& pose, SikWorld& world) const;
  double flexion_for_reach(const SikLimb& limb, const Geometry& g, double reach, bool limits) const;
  Eigen::Quaterniond aim(const Geometry& g, double flexion, const Eigen::Vector3d& direction) const;
  // Lines 1-6: the flexion the distance needs, A aimed at the target, both within the limits.
  void aim_from_neutral(const SikLimb& limb, const Geometry& g, const Eigen::Vector3d& target,
                        bool limits, Pose& pose, SikWorld& world) const;
  void update(const SikLimb& limb, const Pose& pose, SikWorld& world) const;
  // Steps 8-12: turn A about its bone so the target lies in B's flexion plane, then flex B.
  void bend_toward(const SikLimb& limb, const Geometry& g, const Eigen::Vector3d& target,
                   bool limits, Pose& pose, SikWorld& world) const;
  // Turns the ankle so that the foot lies level, its front along the pelvis' heading.
  void level_foot(const SikLimb& leg, Pose& pose, SikWorld& world) const;
  void clear_elbow(const SikLimb& limb, int side, const Eigen::Vector3d& target, bool limits,
                   Pose& pose, SikWorld& world) const;
  void clear_wrist(const SikLimb& limb, int side, bool limits, Pose& pose, SikWorld& world) const;
  // Turns joint j by `world_turn` (a rotation in the world frame about the joint's centre).
  void turn(int j, const Eigen::Quaterniond& world_turn, Pose& pose, const SikWorld& world) const;

  const SikBody& body_;
  const SikLimits& limits_;
  const SikCollider* collider_;
  SikSwivel swivel_;
  std::array<Geometry, 2> arm_, leg_;
};

}  // namespace simcap
