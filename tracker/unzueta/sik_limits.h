// Biomechanical joint limits of SIK (Unzueta 2009 §4.5) on an H-Anim skeleton: a swing cone and
// a twist range for ball joints (spine, clavicles, shoulders, hips), a flexion range for hinges.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_swing_cone.h"

namespace simcap {

enum class SikLimitKind { free, ball, hinge };

struct SikJointLimit {
  SikLimitKind kind = SikLimitKind::free;
  // ball: the joint's segment direction d = q * pole may swing away from its neutral direction
  // `pole` by psi <= cone(theta), where theta is measured from `theta_zero` (anatomically
  // anterior) toward `theta_ninety` (lateral for limbs, superior for clavicles); the twist about
  // `pole` left after the shortest swing lies in [min, max].
  // hinge: a pure rotation about `pole` (the SikBody hinge axis) by an angle in [min, max].
  Eigen::Vector3d pole = Eigen::Vector3d::UnitY();
  Eigen::Vector3d theta_zero = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d theta_ninety = Eigen::Vector3d::UnitX();
  int cone = -1;  // index into SikLimits' cones (ball only)
  double min = 0.0, max = 0.0;
};

// Swing (psi, theta) and twist of a rotation about a ball joint's pole, radians.
struct SwingTwist {
  double psi = 0.0, theta = 0.0, twist = 0.0;
};

class SikLimits {
 public:
  // The table in sik_limits.cpp (clinical ranges, each with its source) applied to `body`.
  explicit SikLimits(const SikBody& body);

  const SikJointLimit& operator[](int joint) const { return joints_[joint]; }
  double max_swing(int joint, double theta) const;
  SwingTwist decompose(int joint, const Eigen::Quaterniond& q) const;

  // The rotation within the limit nearest to q in Unzueta's sense: the swing is pulled back
  // along its meridian (same theta) to the cone, then the twist is clamped. Free joints: q.
  Eigen::Quaterniond clamp(int joint, const Eigen::Quaterniond& q) const;
  // How far q lies outside the limit, radians (0 inside): the largest of the swing excess, the
  // twist excess and, for hinges, the off-axis part.
  double excess(int joint, const Eigen::Quaterniond& q) const;

 private:
  std::vector<SikJointLimit> joints_;
  std::vector<SwingCone> cones_;
};

}  // namespace simcap
