// Procedural motions (generate_procedural, declared in motion_source.h). The gaits work like a
// footstep planner: the pelvis follows a ground path; each foot is planted, flat, under its hip
// early in its stance phase and stays there (the heel rising about the ball before
// toe-off); swing feet travel between plants; the pelvis height is the highest both legs
// reach; legs are solved by analytic two-bone IK. So feet never slide or sink by construction,
// and tests check it with measure_feet().
#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>

#include "core/error.h"
#include "core/limits.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "models/procedural_actions.h"
#include "models/procedural_rig.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;

using namespace procedural;

// A key pose of the left arm at the fraction `at` of a gesture (the right arm mirrors it):
// shoulder abduction (out sideways), flexion (negative: forward), twist about the upper arm and
// elbow flexion (negative), radians, in the conventions of models/joint_limits.h.
struct ArmKey {
  double at, abduction, flexion, twist, elbow;
};

// The gestures' keys, within Gomez Jauregui's Table 2-1 limits (so that his upper body can
// reach every pose); simcap's choices after the thesis's descriptions (§3.6.2).
std::vector<ArmKey> gesture_keys(const std::string& name) {
  const ArmKey rest0{0.0, 0.08, 0.0, 0.0, -0.12}, rest1{1.0, 0.08, 0.0, 0.0, -0.12};
  if (name == "raise") {
    return {rest0,
            {0.12, 0.08, 0.0, 0.0, -0.12},
            {0.40, 1.60, -0.20, 0.0, -0.30},
            {0.60, 1.60, -0.20, 0.0, -0.30},
            {0.90, 0.08, 0.0, 0.0, -0.12},
            rest1};
  }
  if (name == "joy") {
    return {rest0,
            {0.10, 0.08, 0.0, 0.0, -0.12},
            {0.30, 0.60, -1.40, 0.30, -1.60},
            {0.40, 0.90, -1.75, 0.20, -0.90},
            {0.55, 0.50, -1.30, 0.30, -1.80},
            {0.85, 0.08, 0.0, 0.0, -0.12},
            rest1};
  }
  if (name == "exclaim") {
    return {rest0,
            {0.10, 0.08, 0.0, 0.0, -0.12},
            {0.30, 0.50, -0.90, -0.80, -0.60},
            {0.50, 0.90, -0.50, -0.40, -0.30},
            {0.70, 0.30, -1.10, -0.90, -1.20},
            {0.90, 0.08, 0.0, 0.0, -0.12},
            rest1};
  }
  if (name == "ask") {
    return {rest0,
            {0.10, 0.08, 0.0, 0.0, -0.12},
            {0.30, 0.15, -1.25, 0.0, -0.35},
            {0.48, 0.30, -0.60, 0.0, -1.70},
            {0.66, 0.20, -1.30, 0.0, -0.30},
            {0.90, 0.08, 0.0, 0.0, -0.12},
            rest1};
  }
  std::string known;
  for (const auto& g : gesture_names()) known += (known.empty() ? "" : ", ") + g;
  throw Error("procedural motion: unknown gesture '" + name + "' (expected one of " + known + ")");
}

struct Gait {
  double stride_s = 1.0;    // one left and one right step
  double stance = 0.6;      // fraction of the stride a foot is on the floor
  double heel_rise = 0.0;   // rad, at toe-off
  double lift = 0.0;        // m, swing foot clearance
  double sway = 0.0;        // m, lateral pelvis shift towards the stance foot
  double pelvis_yaw = 0.0;  // rad, the pelvis turns with the swinging leg
  double arm_swing = 0.0;   // rad, shoulder flexion amplitude
  double lean = 0.0;        // rad, forward trunk lean
  double toe_drop = 0.0;    // rad, toes down in mid-swing
};

class Generator : Rig {
 public:
  Generator(const ProceduralSpec& spec, const Skeleton& skeleton) : Rig(skeleton), spec_(spec) {
    const double leg_length = this->leg_length();

    const std::string& kind = spec_.kind;
    const bool travels = kind == "walk_path" || kind == "turnaround";
    if (travels || kind == "walk_in_place" || kind == "turn") {
      if (!(spec_.speed_m_s > 0)) throw Error("procedural motion: speed_m_s must be positive");
      // Cadence grows with the square root of speed (about 1.8 steps/s at 1.2 m/s for an
      // adult, whose hip-to-ankle length is 0.86 m) and falls with leg length as a pendulum's
      // rate does; in place, speed only scales the step rate.
      const double relative = spec_.speed_m_s / 1.2;
      const double steps_per_s =
          1.8 * (travels ? std::sqrt(relative) : relative) * std::sqrt(0.86 / leg_length);
      gait_.stride_s = 2.0 / steps_per_s;
      const double step = travels ? spec_.speed_m_s / steps_per_s : 0.0;
      // The toes stay flat as the heel rises, within their 40 degree extension.
      gait_.heel_rise = std::min(0.68, 0.14 + 0.9 * step / leg_length);
      gait_.lift = (travels ? 0.07 : 0.10) * leg_length;
      gait_.sway = 0.025;
      gait_.pelvis_yaw = travels ? 0.07 : 0.0;
      gait_.arm_swing = travels ? 0.35 : 0.2;
      gait_.lean = travels ? 0.05 : 0.02;
      gait_.toe_drop = travels ? 0.12 : 0.3;
      if (kind == "walk_path" && !(spec_.path_radius > 0)) {
        throw Error("procedural motion: path_radius must be positive");
      }
    } else if (kind == "arm_gesture") {
      gesture_ = gesture_keys(spec_.gesture);
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
    } else if (kind == "arm_gesture") {
      stand(t, pose);
      gesture(t, pose);
    } else {
      walk(t, pose);
    }
    return pose;
  }

 private:
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
    } else if (spec_.kind == "turnaround") {
      turnaround_path(spec_, t, ground, heading);
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
    // The foot points where the pelvis points half way through the stance, so that a turning
    // pelvis twists the hip equally far either way.
    path(t_mid + 0.1 * gait_.stance * gait_.stride_s, &ground, &p.yaw);
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
    const double w = smoothstep((u - 0.05) / 0.85);
    const Eigen::Vector3d from = ankle_of(side, now, gait_.heel_rise);
    const Eigen::Vector3d to = ankle_of(side, next, 0);
    const double lift = gait_.lift * smoothstep(u / 0.2) * smoothstep((1 - u) / 0.25);
    f.ankle = (1 - w) * from + w * to + Eigen::Vector3d(0, lift, 0);
    f.yaw = now.yaw + w * std::remainder(next.yaw - now.yaw, 2 * kPi);
    // The foot levels early in the swing, clearing the toes, and drops its toes in mid-swing as
    // the ankle relaxes under the tilted shin; the toes straighten once off the floor.
    f.pitch = gait_.heel_rise * (1 - smoothstep(u / 0.4)) + gait_.toe_drop * bump(u);
    f.toes = smoothstep(u / 0.3);
    f.air = smoothstep(u / 0.15) * smoothstep((1 - u) / 0.25);
    return f;
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
      // More bent in front than behind, linearly so that the elbow's speed never jumps.
      pose.rotations[elbow_[side]] = rot_x(-(0.25 + 0.3 * (gait_.arm_swing - back)));
    }
    stand_on(pose, feet, nullptr);
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
    stand_on(pose, feet, nullptr);
  }

  // The arms at time t along the gesture's keys (smoothstep between keys), the left arm a little
  // ahead of the right so that the two are never mirror images; the trunk turns and leans a
  // little with the arms.
  void gesture(double t, Pose& pose) const {
    const double u = t / duration();
    for (int side = 0; side < 2; ++side) {
      const ArmKey k = arm_at(std::clamp(u - 0.03 * side, 0.0, 1.0));
      const double mirror = side == 0 ? 1.0 : -1.0;
      pose.rotations[shoulder_[side]] =
          rot_z(mirror * k.abduction) * rot_x(k.flexion) * rot_y(mirror * k.twist);
      pose.rotations[elbow_[side]] = rot_x(k.elbow);
    }
    const ArmKey k = arm_at(std::clamp(u, 0.0, 1.0));
    rotate(pose, chest_, rot_x(-0.08 * k.flexion) * rot_y(0.05 * std::sin(2 * kPi * u)));
  }
  ArmKey arm_at(double u) const {
    size_t i = 1;
    while (i + 1 < gesture_.size() && gesture_[i].at < u) ++i;
    const ArmKey& a = gesture_[i - 1];
    const ArmKey& b = gesture_[i];
    const double w = smoothstep((u - a.at) / std::max(1e-9, b.at - a.at));
    return {u, a.abduction + w * (b.abduction - a.abduction),
            a.flexion + w * (b.flexion - a.flexion), a.twist + w * (b.twist - a.twist),
            a.elbow + w * (b.elbow - a.elbow)};
  }

  ProceduralSpec spec_;
  Gait gait_;
  std::vector<ArmKey> gesture_;
};

}  // namespace

const std::vector<std::string>& procedural_kinds() {
  static const std::vector<std::string> kinds = [] {
    std::vector<std::string> k = {"stand",     "tpose", "walk_in_place", "walk_path",
                                  "arm_raise", "turn",  "turnaround",    "arm_gesture"};
    k.insert(k.end(), action_kinds().begin(), action_kinds().end());
    k.push_back("gestures");
    return k;
  }();
  return kinds;
}

const std::vector<std::string>& gesture_names() {
  static const std::vector<std::string> names = {"raise", "joy", "exclaim", "ask"};
  return names;
}

Motion generate_procedural(const ProceduralSpec& spec, const Skeleton& skeleton, double fps) {
  if (!(fps > 0) || !std::isfinite(fps)) {
    throw Error("procedural motion: frame rate must be positive, got " + std::to_string(fps));
  }
  if (spec.kind == "gestures") return generate_gestures(spec.gestures, skeleton, fps);
  if (!(spec.duration_s >= 0) || !std::isfinite(spec.duration_s)) {
    throw Error("procedural motion: duration_s must be zero or positive");
  }
  if (const auto p = parameter_problem(spec)) {
    throw Error("procedural motion " + spec.kind + ": " + p->key + " " + p->message);
  }
  std::function<Pose(double)> pose_at;
  if (is_action(spec.kind)) {
    pose_at = action_poses(spec, skeleton);
  } else {
    pose_at = [generator = std::make_shared<const Generator>(spec, skeleton)](double t) {
      return generator->pose_at(t);
    };
  }
  Motion motion;
  motion.fps = fps;
  const int frames =
      limits::frames_within(spec.duration_s, fps, skeleton.size(), "procedural motion");
  for (int i = 0; i < frames; ++i) motion.frames.push_back(pose_at(i / fps));
  return motion;
}

}  // namespace simcap
