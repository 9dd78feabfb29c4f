// The kinematics the procedural motions share (procedural_motion.cpp, procedural_actions.cpp):
// the humanoid's joints by H-Anim name, easing curves, aiming bones, two-bone IK and balance.
#pragma once

#include <Eigen/Geometry>
#include <initializer_list>
#include <span>
#include <vector>

#include "models/body_mass.h"
#include "models/pose.h"
#include "models/skeleton.h"

namespace simcap::procedural {

Eigen::Quaterniond rot_x(double a);
Eigen::Quaterniond rot_y(double a);
Eigen::Quaterniond rot_z(double a);

// 0 below 0, 1 above 1, zero slope at both ends.
double smoothstep(double x);

// sin^2(pi u): 0 with zero slope at u = 0 and 1 (and outside), 1 at u = 0.5.
double bump(double u);

// 0 up to -k, x from k on, a parabola between: a ramp whose slope never jumps.
double soft_ramp(double x, double k);

// The most the ankles flex up (rad) under weight; AAOS allows 20 degrees.
inline constexpr double kDorsiflexion = 0.3;

// A key of a piecewise cubic Hermite curve: its value and rate of change at time t.
template <class T>
struct Key {
  double t;
  T value;
  T rate;
};

// The C1 curve through `keys` (ascending t). Before the first and after the last key it holds the
// end values, so end keys with zero rates keep the velocity continuous there too.
template <class T>
T hermite(std::span<const Key<T>> keys, double t) {
  if (t <= keys.front().t) return keys.front().value;
  if (t >= keys.back().t) return keys.back().value;
  size_t i = 1;
  while (keys[i].t < t) ++i;
  const Key<T>& a = keys[i - 1];
  const Key<T>& b = keys[i];
  const double h = b.t - a.t, u = (t - a.t) / h, u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * a.value + (u3 - 2 * u2 + u) * h * a.rate +
         (-2 * u3 + 3 * u2) * b.value + (u3 - u2) * h * b.rate;
}

// World rotation that turns a bone lying along `rest` in the neutral pose (facing +Z) into one
// along `bone` facing `forward`: a hinge below it then bends in the plane of bone and forward.
Eigen::Quaterniond aim(const Eigen::Vector3d& rest, const Eigen::Vector3d& bone,
                       const Eigen::Vector3d& forward);

struct Leg {
  int hip, knee, ankle, ball;
  double thigh, shin;               // segment lengths
  Eigen::Vector3d ball_from_root;   // neutral, horizontal part only
  Eigen::Vector3d ankle_from_ball;  // neutral
  double ball_height;               // neutral height of the ball joint's centre
};

// Where a foot is: its ankle centre, heading and pitch about the ball (heel up positive); how
// far the toes follow the foot's pitch (0: flat on the floor, 1: straight); and how much it is in
// the air (0 .. 1), where the toes drop as far as needed to keep the ankle within 17 degrees of
// dorsiflexion under a tilted shin.
struct Foot {
  Eigen::Vector3d ankle;
  double yaw = 0, pitch = 0, toes = 0, air = 0;
};

// The joints of a humanoid from build_humanoid (H-Anim names) and what moves them. Throws Error
// for a skeleton without the H-Anim leg and arm joints.
class Rig {
 public:
  explicit Rig(const Skeleton& skeleton);

 protected:
  Eigen::Vector3d c(int j) const { return s_[j].center; }
  int first_of(std::initializer_list<const char*> names) const;
  void rotate(Pose& pose, int joint, const Eigen::Quaterniond& q) const {
    if (joint >= 0) pose.rotations[joint] = q * pose.rotations[joint];
  }
  double leg_length() const { return legs_[0].thigh + legs_[0].shin; }
  // The foot of `side` standing flat where it stands in the neutral pose.
  Foot neutral_foot(int side) const;

  // Two-bone IK of one leg for the pose's current pelvis, the knee bending towards the foot's
  // heading, then the foot and toes.
  void solve_leg(int side, const Foot& f, Pose& pose) const;
  // The forward tilt of the shin of `side` (knee ahead of the ankle) in the vertical plane of
  // `heading` (rad): the ankle's dorsiflexion when the foot is flat.
  double shin_tilt(const Pose& pose, int side, double heading) const;
  // `foot` pitched to `pitch` about its ball, which stays where it was.
  Foot on_ball(int side, const Foot& foot, double pitch) const;

  // Two-bone IK of one arm for the pose's current trunk: the wrist towards `wrist`, the forearm
  // bending from the upper arm towards `bend`. The hand continues the forearm.
  void solve_arm(int side, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend,
                 Pose& pose) const;

  // The highest root that both legs reach (with a little knee bend left), capped at `cap`.
  double pelvis_height(const Eigen::Vector3d& root_xz, const Eigen::Quaterniond& root_rotation,
                       const Foot (&feet)[2], double cap) const;

  // The middle of a flat foot's sole on the floor (x, z).
  Eigen::Vector2d sole_centre(int side, const Foot& f) const;
  // Where the weight goes: the middle of the soles of flat feet, the balls of raised ones.
  Eigen::Vector2d support(const Foot (&feet)[2]) const;
  // Solves the legs for `planted` feet, their heels rising further (about the balls) as far as
  // the ankles' dorsiflexion under weight needs; feet leaving the floor hand over to their own
  // guard (Foot::air). With `mass`, the root is first balanced over the support.
  void stand_on(Pose& pose, const Foot (&planted)[2], const BodyMass* mass) const;

  // Moves the root horizontally (legs re-solved for `feet`) until the whole-body centre of mass of
  // `mass` lies above `support` (x, z), as a person standing still keeps it.
  void balance(const BodyMass& mass, Pose& pose, const Foot (&feet)[2],
               const Eigen::Vector2d& support) const;

  const Skeleton& s_;
  int root_ = 0, lumbar_ = -1, thorax_ = -1, chest_ = -1, head_ = -1;
  std::vector<int> spine_;  // vl5 .. vt1, the trunk's flexing joints, lowest first
  Leg legs_[2];
  int shoulder_[2], elbow_[2], wrist_[2];
  int toe_tip_[2];  // the toes' end sites (the balls where a skeleton has none)

 private:
  // Rotates `upper` and `middle` (a hinge about its +X, bending with the sign of
  // `flexion_sign`: +1 for a knee, -1 for an elbow) so that `end` goes towards `target` (as far
  // as the bones reach), the lower bone bending towards `forward`. Returns the world rotation of
  // `middle`.
  Eigen::Quaterniond two_bone(int upper, int middle, int end, const Eigen::Vector3d& target,
                              const Eigen::Vector3d& forward, double flexion_sign,
                              Pose& pose) const;
};

}  // namespace simcap::procedural
