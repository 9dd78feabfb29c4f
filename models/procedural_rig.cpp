#include "models/procedural_rig.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "models/body_mass.h"

namespace simcap::procedural {
namespace {

// Orthonormal frame with its first axis along `along` and its second towards `forward`.
Eigen::Matrix3d frame(const Eigen::Vector3d& along, const Eigen::Vector3d& forward) {
  const Eigen::Vector3d a = along.normalized();
  const Eigen::Vector3d f = (forward - forward.dot(a) * a).normalized();
  Eigen::Matrix3d m;
  m << a, f, a.cross(f);
  return m;
}

}  // namespace

Eigen::Quaterniond rot_x(double a) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()));
}
Eigen::Quaterniond rot_y(double a) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()));
}
Eigen::Quaterniond rot_z(double a) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()));
}

double smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3 - 2 * x);
}

double soft_ramp(double x, double k) {
  if (x <= -k) return 0;
  if (x >= k) return x;
  return (x + k) * (x + k) / (4 * k);
}

double bump(double u) {
  const double s = std::sin(std::numbers::pi * std::clamp(u, 0.0, 1.0));
  return s * s;
}

Eigen::Quaterniond aim(const Eigen::Vector3d& rest, const Eigen::Vector3d& bone,
                       const Eigen::Vector3d& forward) {
  return Eigen::Quaterniond(frame(bone, forward) *
                            frame(rest, Eigen::Vector3d::UnitZ()).transpose());
}

Rig::Rig(const Skeleton& skeleton) : s_(skeleton) {
  root_ = s_.require("humanoid_root");
  if (root_ != 0) throw Error("procedural motion: humanoid_root must be the skeleton's root");
  for (int side = 0; side < 2; ++side) {
    const std::string p = side == 0 ? "l_" : "r_";
    Leg& leg = legs_[side];
    leg.hip = s_.require(p + "hip");
    leg.knee = s_.require(p + "knee");
    leg.ankle = s_.require(p + "talocrural");
    leg.ball = s_.require(p + "metatarsophalangeal_2");
    leg.thigh = (c(leg.knee) - c(leg.hip)).norm();
    leg.shin = (c(leg.ankle) - c(leg.knee)).norm();
    leg.ball_from_root = c(leg.ball) - c(root_);
    leg.ball_from_root.y() = 0;
    leg.ankle_from_ball = c(leg.ankle) - c(leg.ball);
    leg.ball_height = c(leg.ball).y();
    shoulder_[side] = s_.require(p + "shoulder");
    elbow_[side] = s_.require(p + "elbow");
    wrist_[side] = s_.require(p + "radiocarpal");
    toe_tip_[side] = s_.find(p + "toe_tip") >= 0 ? s_.find(p + "toe_tip") : leg.ball;
  }
  lumbar_ = first_of({"vl5", "vl3", "vl1"});
  thorax_ = first_of({"vl1", "vt10", "vt6"});
  chest_ = first_of({"vt6", "vt10", "vt1"});
  head_ = first_of({"skullbase", "vc4", "vc7"});
  for (const char* name : {"vl5", "vl3", "vl1", "vt10", "vt6", "vt1"}) {
    if (s_.find(name) >= 0) spine_.push_back(s_.find(name));
  }
}

int Rig::first_of(std::initializer_list<const char*> names) const {
  for (const char* n : names) {
    if (s_.find(n) >= 0) return s_.find(n);
  }
  return -1;
}

Foot Rig::neutral_foot(int side) const {
  Foot f;
  f.ankle = c(legs_[side].ankle);
  return f;
}

Eigen::Quaterniond Rig::two_bone(int upper, int middle, int end, const Eigen::Vector3d& target,
                                 const Eigen::Vector3d& forward, double flexion_sign,
                                 Pose& pose) const {
  const auto world = forward_kinematics(s_, pose);
  const Eigen::Vector3d base = world[upper].translation();
  // The hinge turns the lower bone about the middle joint's +X: in the upper bone's frame the end
  // lies at e + R_x(angle) g, whose length is fixed by the angle, so the angle is found from the
  // distance to the target (|e + R_x g|^2 = |e|^2 + |g|^2 + 2 (A + B cos + C sin)).
  const Eigen::Vector3d e = c(middle) - c(upper), g = c(end) - c(middle);
  const double a = e.x() * g.x(), b = e.y() * g.y() + e.z() * g.z(),
               cc = e.z() * g.y() - e.y() * g.z();
  const double r = std::hypot(b, cc), base_sq = e.squaredNorm() + g.squaredNorm();
  const double d = (target - base).norm();
  const double cos_term = std::clamp((0.5 * (d * d - base_sq) - a) / r, -1.0, 1.0);
  const double angle = std::atan2(cc, b) + flexion_sign * std::acos(cos_term);
  const Eigen::Vector3d local_end = e + rot_x(angle) * g;
  // Turn the upper bone so that the end points at the target and the hinge axis lies across
  // `forward`, which the lower bone then bends towards.
  const Eigen::Vector3d to_target = (target - base).normalized();
  const Eigen::Vector3d hinge = forward.cross(to_target);
  Eigen::Matrix3d from, to;
  const Eigen::Vector3d x_local = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d from_2 =
      (x_local - x_local.dot(local_end.normalized()) * local_end.normalized()).normalized();
  const Eigen::Vector3d to_2 = (hinge - hinge.dot(to_target) * to_target).normalized();
  from << local_end.normalized(), from_2, local_end.normalized().cross(from_2);
  to << to_target, to_2, to_target.cross(to_2);
  const Eigen::Quaterniond first(to * from.transpose());
  const Eigen::Quaterniond parent(world[s_[upper].parent].linear());
  pose.rotations[upper] = (parent.conjugate() * first).normalized();
  pose.rotations[middle] = rot_x(angle);
  return (first * rot_x(angle)).normalized();
}

void Rig::solve_leg(int side, const Foot& f, Pose& pose) const {
  const Leg& leg = legs_[side];
  // The knee bends towards the foot's heading, the bending plane turned about the hip-ankle
  // line until the ankle, which has no twist, needs none (Newton steps on the turn).
  const Eigen::Vector3d hip = forward_kinematics(s_, pose)[leg.hip].translation();
  const Eigen::Vector3d axis = (f.ankle - hip).normalized();
  // A leg lifted out in front (a kick) bends its knee upwards, where the heading no longer
  // says which way is forward.
  Eigen::Vector3d heading = rot_y(f.yaw) * Eigen::Vector3d::UnitZ();
  const double ahead = axis.dot(heading) - 0.6, k = 0.2;
  if (ahead > -k) {
    heading +=
        2 * Eigen::Vector3d::UnitY() * (ahead < k ? (ahead + k) * (ahead + k) / (4 * k) : ahead);
  }
  Eigen::Quaterniond shin, foot;
  const auto ankle_twist = [&](double turn) {
    shin = two_bone(leg.hip, leg.knee, leg.ankle, f.ankle, Eigen::AngleAxisd(turn, axis) * heading,
                    1, pose);
    const Eigen::Matrix3d r = (shin.conjugate() * foot).toRotationMatrix();
    return std::atan2(-r(2, 0), r(2, 2));
  };
  const auto solve = [&](double pitch) {
    foot = rot_y(f.yaw) * rot_x(pitch);
    double turn = 0;
    for (int i = 0; i < 2; ++i) {
      const double twist = ankle_twist(turn);
      turn -= twist / ((ankle_twist(turn + 1e-4) - twist) / 1e-4);
    }
    ankle_twist(turn);
  };
  double pitch = f.pitch;
  solve(pitch);
  if (f.air > 0) {
    // The ankle's dorsiflexion is the shin's tilt less the foot's pitch.
    const double least = shin_tilt(pose, side, f.yaw) - 0.3, k = 0.05;
    const double smooth_max =
        0.5 * (pitch + least + std::sqrt((pitch - least) * (pitch - least) + k * k));
    pitch += f.air * (smooth_max - pitch);
    solve(pitch);
  }
  pose.rotations[leg.ankle] = (shin.conjugate() * foot).normalized();
  pose.rotations[leg.ball] = rot_x(-(1 - f.toes) * pitch);
}

double Rig::shin_tilt(const Pose& pose, int side, double heading) const {
  const auto world = forward_kinematics(s_, pose);
  const Eigen::Vector3d up =
      world[legs_[side].knee].translation() - world[legs_[side].ankle].translation();
  return std::atan2(up.dot(rot_y(heading) * Eigen::Vector3d::UnitZ()), up.y());
}

Foot Rig::on_ball(int side, const Foot& foot, double pitch) const {
  const Eigen::Quaterniond yaw = rot_y(foot.yaw);
  const Eigen::Vector3d& to_ankle = legs_[side].ankle_from_ball;
  Foot f = foot;
  f.ankle = foot.ankle + yaw * (rot_x(pitch) * to_ankle - rot_x(foot.pitch) * to_ankle);
  f.pitch = pitch;
  return f;
}

void Rig::solve_arm(int side, const Eigen::Vector3d& wrist, const Eigen::Vector3d& bend,
                    Pose& pose) const {
  two_bone(shoulder_[side], elbow_[side], wrist_[side], wrist, bend, -1, pose);
  pose.rotations[wrist_[side]] = Eigen::Quaterniond::Identity();
}

double Rig::pelvis_height(const Eigen::Vector3d& root_xz, const Eigen::Quaterniond& root_rotation,
                          const Foot (&feet)[2], double cap) const {
  // A smooth minimum (never above the true one) keeps the pelvis velocity continuous where the
  // limiting leg changes.
  const auto smooth_min = [](double a, double b) {
    const double k = 0.02;
    return 0.5 * (a + b - std::sqrt((a - b) * (a - b) + k * k));
  };
  double height = cap;
  for (int side = 0; side < 2; ++side) {
    const Leg& leg = legs_[side];
    const Eigen::Vector3d hip = root_rotation * (c(leg.hip) - c(root_));
    const double reach = 0.995 * (leg.thigh + leg.shin);
    const double dh = std::hypot(root_xz.x() + hip.x() - feet[side].ankle.x(),
                                 root_xz.z() + hip.z() - feet[side].ankle.z());
    const double rise = dh < reach ? std::sqrt(reach * reach - dh * dh) : 0.0;
    height = smooth_min(height, feet[side].ankle.y() + rise - hip.y());
  }
  return height;
}

Eigen::Vector2d Rig::sole_centre(int side, const Foot& f) const {
  // A third of the way from the ankle to the toe tip lies half way between heel and toe.
  const Eigen::Vector3d toe = c(toe_tip_[side]) - c(legs_[side].ankle);
  const Eigen::Vector3d p = f.ankle + rot_y(f.yaw) * (toe / 3);
  return {p.x(), p.z()};
}

Eigen::Vector2d Rig::support(const Foot (&feet)[2]) const {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int side = 0; side < 2; ++side) {
    const Foot& f = feet[side];
    const Eigen::Vector3d ball =
        f.ankle - rot_y(f.yaw) * rot_x(f.pitch) * legs_[side].ankle_from_ball;
    const double w = smoothstep(f.pitch / 0.05);  // the heel is off the floor
    sum += (1 - w) * sole_centre(side, f) + w * Eigen::Vector2d(ball.x(), ball.z());
  }
  return sum / 2;
}

void Rig::stand_on(Pose& pose, const Foot (&planted)[2], const BodyMass* mass) const {
  Foot feet[2] = {planted[0], planted[1]};
  const double height = pose.root_position.y();  // as asked; each balance may only lower it
  const auto settle = [&] {
    pose.root_position.y() = height;
    if (mass) {
      balance(*mass, pose, feet, support(feet));
    } else {
      solve_leg(0, feet[0], pose);
      solve_leg(1, feet[1], pose);
    }
  };
  for (int i = 0; i < 3; ++i) {
    settle();
    for (int side = 0; side < 2; ++side) {
      const Foot& f = planted[side];
      const double over = shin_tilt(pose, side, f.yaw) - kDorsiflexion - f.pitch;
      feet[side] = on_ball(side, f, f.pitch + (1 - f.air) * soft_ramp(over, 0.05));
    }
  }
  settle();
}

void Rig::balance(const BodyMass& mass, Pose& pose, const Foot (&feet)[2],
                  const Eigen::Vector2d& support) const {
  // The legs' share of the mass moves less than the root, so a few fixed-point steps converge;
  // a fixed count keeps the result a smooth, deterministic function of the pose. The root comes
  // down where the legs would not reach.
  const double cap = pose.root_position.y();
  const Eigen::Quaterniond root(pose.rotations[root_]);
  for (int i = 0; i < 4; ++i) {
    pose.root_position.y() = pelvis_height(pose.root_position, root, feet, cap);
    solve_leg(0, feet[0], pose);
    solve_leg(1, feet[1], pose);
    const Eigen::Vector3d com = mass.center(joint_positions(s_, pose));
    pose.root_position.x() += support.x() - com.x();
    pose.root_position.z() += support.y() - com.z();
  }
  pose.root_position.y() = pelvis_height(pose.root_position, root, feet, cap);
  solve_leg(0, feet[0], pose);
  solve_leg(1, feet[1], pose);
}

}  // namespace simcap::procedural
