// Procedural motions (generate_procedural, declared in motion_source.h). The gaits work like a
// footstep planner: the pelvis follows a ground path; each foot is planted, flat, under its hip
// early in its stance phase and stays there (the heel rising about the ball before
// toe-off); swing feet travel between plants; the pelvis height is the highest both legs
// reach; legs are solved by analytic two-bone IK. So feet never slide or sink by construction,
// and tests check it with measure_feet().
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/motion_source.h"
#include "models/pose.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;

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

// Orthonormal frame with its first axis along `along` and its second towards `forward`.
Eigen::Matrix3d frame(const Eigen::Vector3d& along, const Eigen::Vector3d& forward) {
  const Eigen::Vector3d a = along.normalized();
  const Eigen::Vector3d f = (forward - forward.dot(a) * a).normalized();
  Eigen::Matrix3d m;
  m << a, f, a.cross(f);
  return m;
}

// World rotation that turns a bone lying along `rest` in the neutral pose (facing +Z) into one
// along `bone` facing `forward`: bends stay in the sagittal plane of the foot.
Eigen::Quaterniond aim(const Eigen::Vector3d& rest, const Eigen::Vector3d& bone,
                       const Eigen::Vector3d& forward) {
  return Eigen::Quaterniond(frame(bone, forward) *
                            frame(rest, Eigen::Vector3d::UnitZ()).transpose());
}

struct Leg {
  int hip, knee, ankle, ball;
  double thigh, shin;               // segment lengths
  Eigen::Vector3d ball_from_root;   // neutral, horizontal part only
  Eigen::Vector3d ankle_from_ball;  // neutral
  double ball_height;               // neutral height of the ball joint's centre
};

// Where a foot is: its ankle centre, heading and heel-rise pitch (toes down, about the ball).
struct Foot {
  Eigen::Vector3d ankle;
  double yaw = 0, pitch = 0;
};

struct Gait {
  double stride_s = 1.0;    // one left and one right step
  double stance = 0.6;      // fraction of the stride a foot is on the floor
  double heel_rise = 0.0;   // rad, at toe-off
  double lift = 0.0;        // m, swing foot clearance
  double sway = 0.0;        // m, lateral pelvis shift towards the stance foot
  double pelvis_yaw = 0.0;  // rad, the pelvis turns with the swinging leg
  double arm_swing = 0.0;   // rad, shoulder flexion amplitude
  double lean = 0.0;        // rad, forward trunk lean
};

class Generator {
 public:
  Generator(const ProceduralSpec& spec, const Skeleton& skeleton) : spec_(spec), s_(skeleton) {
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
    }
    lumbar_ = first_of({"vl5", "vl3", "vl1"});
    thorax_ = first_of({"vl1", "vt10", "vt6"});
    chest_ = first_of({"vt6", "vt10", "vt1"});
    head_ = first_of({"skullbase", "vc4", "vc7"});
    const double leg_length = legs_[0].thigh + legs_[0].shin;

    const std::string& kind = spec_.kind;
    if (kind == "walk_path" || kind == "walk_in_place" || kind == "turn") {
      if (!(spec_.speed_m_s > 0)) throw Error("procedural motion: speed_m_s must be positive");
      // Cadence grows with the square root of speed (about 1.8 steps/s at 1.2 m/s for an
      // adult, whose hip-to-ankle length is 0.86 m) and falls with leg length as a pendulum's
      // rate does; in place, speed only scales the step rate.
      const double relative = spec_.speed_m_s / 1.2;
      const double steps_per_s = 1.8 * (kind == "walk_path" ? std::sqrt(relative) : relative) *
                                 std::sqrt(0.86 / leg_length);
      gait_.stride_s = 2.0 / steps_per_s;
      const double step = kind == "walk_path" ? spec_.speed_m_s / steps_per_s : 0.0;
      gait_.heel_rise = std::min(0.9, 0.14 + 0.9 * step / leg_length);
      gait_.lift = (kind == "walk_path" ? 0.07 : 0.10) * leg_length;
      gait_.sway = 0.025;
      gait_.pelvis_yaw = kind == "walk_path" ? 0.07 : 0.0;
      gait_.arm_swing = kind == "walk_path" ? 0.35 : 0.2;
      gait_.lean = kind == "walk_path" ? 0.05 : 0.02;
      if (kind == "walk_path" && !(spec_.path_radius > 0)) {
        throw Error("procedural motion: path_radius must be positive");
      }
    } else if (kind != "stand" && kind != "tpose" && kind != "arm_raise") {
      std::string known;
      for (const auto& k : procedural_kinds()) known += (known.empty() ? "" : ", ") + k;
      throw Error("procedural motion: unknown kind '" + kind + "' (expected one of " + known + ")");
    }
  }

  Pose pose_at(double t) const {
    Pose pose = Pose::neutral(s_);
    const std::string& kind = spec_.kind;
    if (kind == "tpose" || kind == "arm_raise") {
      const double up = kind == "tpose"
                            ? kPi / 2
                            : 2.95 * 0.5 * (1 - std::cos(2 * kPi * t / duration()));  // 169 deg
      pose.rotations[shoulder_[0]] = rot_z(up);
      pose.rotations[shoulder_[1]] = rot_z(-up);
      return pose;
    }
    if (kind == "stand") {
      stand(t, pose);
    } else {
      walk(t, pose);
    }
    return pose;
  }

 private:
  Eigen::Vector3d c(int j) const { return s_[j].center; }
  int first_of(std::initializer_list<const char*> names) const {
    for (const char* n : names) {
      if (s_.find(n) >= 0) return s_.find(n);
    }
    return -1;
  }
  void rotate(Pose& pose, int joint, const Eigen::Quaterniond& q) const {
    if (joint >= 0) pose.rotations[joint] = q * pose.rotations[joint];
  }
  double duration() const { return spec_.duration_s > 0 ? spec_.duration_s : 1.0; }

  // Ground point under the pelvis and heading at time t (any t, also before 0 and after the end,
  // so that footstep plants are defined for every stance).
  void path(double t, Eigen::Vector3d* ground, double* heading) const {
    *ground = Eigen::Vector3d::Zero();
    *heading = 0;
    if (spec_.kind == "walk_path") {
      const double r = spec_.path_radius, a = spec_.speed_m_s * t / r;
      *ground = Eigen::Vector3d(r - r * std::cos(a), 0, r * std::sin(a));  // centre (r, 0, 0)
      *heading = a;
    } else if (spec_.kind == "turn") {
      *heading = spec_.turn_degrees * kPi / 180 * smoothstep(t / duration());
    }
  }

  // Where a foot stands during its k-th stance: flat, under the hip early in that stance.
  struct Plant {
    Eigen::Vector3d ball;  // centre of the ball (metatarsophalangeal) joint
    double yaw;
  };
  Plant plant(int side, double k) const {
    // The ankle passes under the hip at 40% of stance: the trailing leg, lengthened by the
    // heel rise, reaches further back than the leading leg reaches forward.
    const double t_mid = (k + 0.5 * side + 0.4 * gait_.stance) * gait_.stride_s;
    Eigen::Vector3d ground;
    double heading;
    path(t_mid, &ground, &heading);
    const Leg& leg = legs_[side];
    Plant p{ground + rot_y(heading) * leg.ball_from_root, heading};
    p.ball.y() = leg.ball_height;
    return p;
  }
  // The ankle of a foot whose ball centre is at `ball`, pitched (heel up) about the ball.
  Eigen::Vector3d ankle_of(int side, const Plant& p, double pitch) const {
    return p.ball + rot_y(p.yaw) * rot_x(pitch) * legs_[side].ankle_from_ball;
  }

  Foot foot(int side, double t) const {
    const double x = t / gait_.stride_s - 0.5 * side;
    const double k = std::floor(x), phase = x - k;
    const Plant now = plant(side, k);
    Foot f;
    if (phase < gait_.stance) {
      f.yaw = now.yaw;
      f.pitch = gait_.heel_rise * smoothstep((phase / gait_.stance - 0.5) / 0.5);
      f.ankle = ankle_of(side, now, f.pitch);
      return f;
    }
    const Plant next = plant(side, k + 1);
    // The foot rises before it moves forward and comes down vertically onto its plant, so it
    // does not skim the floor.
    const double u = (phase - gait_.stance) / (1 - gait_.stance);
    const double w = smoothstep((u - 0.1) / 0.85);
    const Eigen::Vector3d from = ankle_of(side, now, gait_.heel_rise);
    const Eigen::Vector3d to = ankle_of(side, next, 0);
    f.ankle = (1 - w) * from + w * to + Eigen::Vector3d(0, gait_.lift * std::sin(kPi * u), 0);
    f.yaw = now.yaw + w * std::remainder(next.yaw - now.yaw, 2 * kPi);
    f.pitch = gait_.heel_rise * (1 - w);
    return f;
  }

  // Two-bone IK of one leg for the pose's current pelvis, then the foot and toes.
  void solve_leg(int side, const Foot& f, Pose& pose) const {
    const Leg& leg = legs_[side];
    const auto world = forward_kinematics(s_, pose);
    const Eigen::Vector3d hip = world[leg.hip].translation();
    const Eigen::Vector3d forward = rot_y(f.yaw) * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d to_ankle = f.ankle - hip;
    const double d = std::clamp(to_ankle.norm(), std::abs(leg.thigh - leg.shin) + 1e-9,
                                leg.thigh + leg.shin - 1e-9);
    const Eigen::Vector3d u = to_ankle.normalized();
    const Eigen::Vector3d w = (forward - forward.dot(u) * u).normalized();
    const double cos_hip =
        (leg.thigh * leg.thigh + d * d - leg.shin * leg.shin) / (2 * leg.thigh * d);
    const Eigen::Vector3d knee =
        hip + leg.thigh * (cos_hip * u + std::sqrt(std::max(0.0, 1 - cos_hip * cos_hip)) * w);
    const Eigen::Vector3d ankle = hip + d * u;
    const Eigen::Quaterniond thigh = aim(c(leg.knee) - c(leg.hip), knee - hip, forward);
    const Eigen::Quaterniond shin = aim(c(leg.ankle) - c(leg.knee), ankle - knee, forward);
    const Eigen::Quaterniond foot = rot_y(f.yaw) * rot_x(f.pitch);
    const Eigen::Quaterniond parent(world[s_[leg.hip].parent].linear());
    pose.rotations[leg.hip] = (parent.conjugate() * thigh).normalized();
    pose.rotations[leg.knee] = (thigh.conjugate() * shin).normalized();
    pose.rotations[leg.ankle] = (shin.conjugate() * foot).normalized();
    pose.rotations[leg.ball] = rot_x(-f.pitch);  // toes stay flat while the heel rises
  }

  // The highest root that both legs reach (with a little knee bend left), capped at `cap`.
  double pelvis_height(const Eigen::Vector3d& root_xz, const Eigen::Quaterniond& root_rotation,
                       const Foot (&feet)[2], double cap) const {
    double height = cap;
    for (int side = 0; side < 2; ++side) {
      const Leg& leg = legs_[side];
      const Eigen::Vector3d hip = root_rotation * (c(leg.hip) - c(root_));
      const double reach = 0.995 * (leg.thigh + leg.shin);
      const double dh = std::hypot(root_xz.x() + hip.x() - feet[side].ankle.x(),
                                   root_xz.z() + hip.z() - feet[side].ankle.z());
      const double rise = dh < reach ? std::sqrt(reach * reach - dh * dh) : 0.0;
      height = std::min(height, feet[side].ankle.y() + rise - hip.y());
    }
    return height;
  }

  void walk(double t, Pose& pose) const {
    const double phase = t / gait_.stride_s;
    const double swing = std::cos(2 * kPi * phase);  // +1 at left heel strike
    Eigen::Vector3d ground;
    double heading;
    path(t, &ground, &heading);
    const double yaw = -gait_.pelvis_yaw * swing;  // left hip forward at left heel strike
    const Eigen::Quaterniond root_rotation = rot_y(heading + yaw);
    // Towards the stance foot: left during left single support (phase 0.1 to 0.5).
    const double sway = gait_.sway * std::sin(2 * kPi * (phase - 0.05));
    const Eigen::Vector3d root_xz = ground + rot_y(heading) * Eigen::Vector3d(sway, 0, 0);
    const Foot feet[2] = {foot(0, t), foot(1, t)};
    pose.root_position = root_xz;
    pose.root_position.y() = pelvis_height(root_xz, root_rotation, feet, c(root_).y() - 0.01);
    pose.rotations[root_] = root_rotation;
    // The chest turns against the pelvis; the head keeps looking along the path.
    rotate(pose, lumbar_, rot_x(gait_.lean));
    rotate(pose, thorax_, rot_y(-1.6 * yaw));
    rotate(pose, head_, rot_y(0.6 * yaw) * rot_x(-gait_.lean));
    // Arms swing against the legs: the left arm is back when the left foot strikes.
    for (int side = 0; side < 2; ++side) {
      const double back = (side == 0 ? 1 : -1) * gait_.arm_swing * swing;
      const double out = side == 0 ? 0.06 : -0.06;
      pose.rotations[shoulder_[side]] = rot_z(out) * rot_x(back);
      pose.rotations[elbow_[side]] = rot_x(-(0.25 + 0.6 * std::max(0.0, -back)));
    }
    solve_leg(0, feet[0], pose);
    solve_leg(1, feet[1], pose);
  }

  void stand(double t, Pose& pose) const {
    const double sway = std::sin(2 * kPi * t / 5.0);
    const Eigen::Vector3d root_xz(0.015 * sway, 0, 0.006 * std::sin(2 * kPi * t / 7.0));
    Foot feet[2];
    for (int side = 0; side < 2; ++side) feet[side].ankle = c(legs_[side].ankle);
    pose.root_position = root_xz;
    pose.root_position.y() =
        pelvis_height(root_xz, Eigen::Quaterniond::Identity(), feet, c(root_).y() - 0.008);
    rotate(pose, chest_, rot_x(0.012 * std::sin(2 * kPi * t / 4.0)));  // breathing
    rotate(pose, head_, rot_y(0.12 * std::sin(2 * kPi * t / 6.0)));
    for (int side = 0; side < 2; ++side) {
      const double out = side == 0 ? 0.05 : -0.05;
      pose.rotations[shoulder_[side]] = rot_z(out) * rot_x(0.04 * std::sin(2 * kPi * t / 5.0 + 1));
      pose.rotations[elbow_[side]] = rot_x(-0.12);
    }
    solve_leg(0, feet[0], pose);
    solve_leg(1, feet[1], pose);
  }

  ProceduralSpec spec_;
  const Skeleton& s_;
  int root_ = 0, lumbar_ = -1, thorax_ = -1, chest_ = -1, head_ = -1;
  Leg legs_[2];
  int shoulder_[2], elbow_[2];
  Gait gait_;
};

}  // namespace

const std::vector<std::string>& procedural_kinds() {
  static const std::vector<std::string> kinds = {"stand",     "tpose",     "walk_in_place",
                                                 "walk_path", "arm_raise", "turn"};
  return kinds;
}

Motion generate_procedural(const ProceduralSpec& spec, const Skeleton& skeleton, double fps) {
  if (!(fps > 0) || !std::isfinite(fps)) {
    throw Error("procedural motion: frame rate must be positive, got " + std::to_string(fps));
  }
  if (!(spec.duration_s >= 0) || !std::isfinite(spec.duration_s)) {
    throw Error("procedural motion: duration_s must be zero or positive");
  }
  const Generator generator(spec, skeleton);
  Motion motion;
  motion.fps = fps;
  const int frames = static_cast<int>(std::floor(spec.duration_s * fps + 1e-6)) + 1;
  for (int i = 0; i < frames; ++i) motion.frames.push_back(generator.pose_at(i / fps));
  return motion;
}

}  // namespace simcap
