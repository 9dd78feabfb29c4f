// The action kinds (procedural_actions.h). Each is a few key poses joined by C1 curves
// (smoothstep or cubic Hermite), so joint velocities never jump; stance feet are given as plants
// and the legs reach them by two-bone IK, so they neither slide nor sink; a person standing on
// the spot keeps the whole-body centre of mass over the feet (Rig::balance), and the jump's pelvis
// flies on a ballistic arc. Lengths are fractions of the body's own (leg length, foot length), so
// every body from build_humanoid gets the same motion to scale.
#include "models/procedural_actions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "core/error.h"
#include "models/procedural_rig.h"

namespace simcap::procedural {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kGravity = 9.81;   // m/s^2
constexpr double kRestS = 0.25;     // standing still before and after an action
constexpr double kStepsPerS = 2.5;  // side steps: the fastest cadence

std::string text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Turnaround: the 180 degree turn takes about five steps at the cadence of the speed.
double turn_s(double speed) {
  return 5 / (1.8 * std::sqrt(speed / 1.2));
}

// Time in the air of a jump whose pelvis rises `height` metres.
double flight_s(double height) {
  return 2 * std::sqrt(2 * height / kGravity);
}

// The shortest repetition each counted action allows (seconds).
double min_cycle_s(const ProceduralSpec& spec) {
  const std::string& k = spec.kind;
  if (k == "jumps") return 1.2 + flight_s(spec.jumps.height_m);
  if (k == "squat") return 1.1;
  if (k == "arms_cross") return 1.0;
  if (k == "side_steps") return 4 / kStepsPerS;
  if (k == "bend_forward") return 1.7;
  return 1.6;  // kick
}

int count_of(const ProceduralSpec& spec) {
  const std::string& k = spec.kind;
  if (k == "jumps") return spec.jumps.count;
  if (k == "squat") return spec.squat.count;
  if (k == "arms_cross") return spec.arms_cross.count;
  if (k == "side_steps") return spec.side_steps.count;
  if (k == "bend_forward") return spec.bend_forward.count;
  if (k == "kick") return spec.kick.count;
  return 0;
}

std::optional<ParameterProblem> outside(const std::string& key, double v, double lo, double hi,
                                        const std::string& unit) {
  const double slack = 1e-9 * std::max(1.0, std::abs(hi));
  if (v >= lo - slack && v <= hi + slack) return std::nullopt;
  return ParameterProblem{
      key, "must be in [" + text(lo) + ", " + text(hi) + "]" + unit + ", got " + text(v)};
}

// 0 -> 1 over the first `rise` of [0, 1], 1, then back to 0 over the last `rise`.
double plateau(double u, double rise) {
  return smoothstep(u / rise) * smoothstep((1 - u) / rise);
}

double sign_of(int side) {
  return side == 0 ? 1.0 : -1.0;
}

template <class T, size_t N>
T curve(const std::array<Key<T>, N>& keys, double t) {
  return hermite<T>(std::span<const Key<T>>(keys), t);
}

// What every action shares: its repetitions spread over the duration between two short rests,
// and the standing pose it starts from.
class Action : protected Rig {
 public:
  Action(const ProceduralSpec& spec, const Skeleton& skeleton)
      : Rig(skeleton), spec_(spec), mass_(skeleton) {
    count_ = std::max(1, count_of(spec));
    cycle_s_ = (spec.duration_s - 2 * kRestS) / count_;
    stand_y_ = c(root_).y() - 0.01 * leg_length();
    for (int side = 0; side < 2; ++side) {
      const std::string p = side == 0 ? "l_" : "r_";
      hand_tip_[side] = s_.require(p + "hand_tip");
    }
    neck_ = s_.require("vc7");
    height_ = c(s_.require("skull_tip")).y();
    foot_length_ = (c(toe_tip_[0]) - c(legs_[0].ankle)).z() * 4 / 3;  // ankle 1/4 from the heel
  }
  virtual ~Action() = default;
  virtual Pose pose_at(double t) const = 0;

 protected:
  struct Phase {
    int index;
    double u;  // 0 .. 1 within repetition `index`
  };
  Phase phase(double t) const {
    const double x = (t - kRestS) / cycle_s_;
    if (x <= 0) return {0, 0.0};
    if (x >= count_) return {count_ - 1, 1.0};
    const int k = std::min(count_ - 1, static_cast<int>(std::floor(x)));
    return {k, x - k};
  }
  // The neutral pose, knees a little soft.
  Pose standing() const {
    Pose pose = Pose::neutral(s_);
    pose.root_position.y() = stand_y_;
    return pose;
  }
  // Trunk flexion (rad) spread over the spine, and the neck turning the head back up by `head`.
  void bend_trunk(Pose& pose, double flexion, double head) const {
    for (int j : spine_) rotate(pose, j, rot_x(flexion / spine_.size()));
    rotate(pose, neck_, rot_x(-head));
  }
  ProceduralSpec spec_;
  BodyMass mass_;
  int count_ = 1;
  double cycle_s_ = 1;
  double stand_y_ = 0;
  double foot_length_ = 0, height_ = 0;
  int hand_tip_[2];
  int neck_ = -1;
};

// Squats: feet a little wider than the hips, the pelvis going down and back with the trunk
// leaning forward and the arms reaching forward to keep the balance. The heels rise as far as
// needed to keep the ankles within 17 degrees of dorsiflexion (AAOS allows 20), the weight then
// moving onto the balls of the feet.
class Squat : public Action {
 public:
  Squat(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    for (int side = 0; side < 2; ++side) {
      feet_[side] = neutral_foot(side);
      feet_[side].ankle.x() *= 1.2;
    }
    drop_ = spec.squat.depth * c(legs_[0].hip).y();
    lean_ = 0.9 * spec.squat.depth;
  }
  Pose pose_at(double t) const override {
    const double s = plateau(phase(t).u, 0.42);
    Pose pose = standing();
    pose.root_position.y() -= s * drop_;
    pose.rotations[root_] = rot_x(s * lean_);
    bend_trunk(pose, 0.5 * s * lean_, 0.8 * s * lean_);
    for (int side = 0; side < 2; ++side) {
      pose.rotations[shoulder_[side]] = rot_z(sign_of(side) * 0.1) * rot_x(-s * 1.4);
      pose.rotations[elbow_[side]] = rot_x(-0.15 - 0.15 * s);
    }
    stand_on(pose, feet_, &mass_);
    return pose;
  }

 private:
  Foot feet_[2];
  double drop_ = 0, lean_ = 0;
};

// Bending forward to touch the floor: the hips flex, the spine rounds, the knees soften, the arms
// hang, and the pelvis goes back to keep the balance. The bend at the bottom is solved so that
// the fingertips come to 1% of the body height above the floor.
class BendForward : public Action {
 public:
  BendForward(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    for (int side = 0; side < 2; ++side) feet_[side] = neutral_foot(side);
    double lo = 0.0, hi = 1.6;
    for (int i = 0; i < 30; ++i) {
      const double mid = 0.5 * (lo + hi);
      const auto p = joint_positions(s_, pose_for(1.0, mid));
      (std::min(p[hand_tip_[0]].y(), p[hand_tip_[1]].y()) > 0.01 * height_ ? lo : hi) = mid;
    }
    lean_ = hi;
  }
  Pose pose_at(double t) const override { return pose_for(plateau(phase(t).u, 0.4), lean_); }

 private:
  Pose pose_for(double s, double lean) const {
    Pose pose = standing();
    pose.root_position.y() -= s * 0.05 * leg_length();
    pose.rotations[root_] = rot_x(s * lean);
    bend_trunk(pose, s * 1.0, s * 0.3);
    const auto world = forward_kinematics(s_, pose);
    for (int side = 0; side < 2; ++side) {
      const double reach = 0.97 * ((c(elbow_[side]) - c(shoulder_[side])).norm() +
                                   (c(wrist_[side]) - c(elbow_[side])).norm());
      solve_arm(side, world[shoulder_[side]].translation() - reach * Eigen::Vector3d::UnitY(),
                Eigen::Vector3d::UnitZ(), pose);
    }
    stand_on(pose, feet_, &mass_);
    return pose;
  }

  Foot feet_[2];
  double lean_ = 0;
};

// Arms crossing in front of the chest, opening out to the sides between crossings and hanging
// at the start and end; the arm on top alternates and passes a tenth of the body height above
// and in front of the other. Wrists are placed relative to the shoulders by two-bone IK.
class ArmsCross : public Action {
 public:
  ArmsCross(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    for (int side = 0; side < 2; ++side) feet_[side] = neutral_foot(side);
    const double h = height_;
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector3d mirror(sign_of(side), 1, 1);
      const Eigen::Vector3d down = 0.95 * (c(wrist_[side]) - c(shoulder_[side]));
      const Eigen::Vector3d open = h * Eigen::Vector3d(0.27, -0.05, 0.10).cwiseProduct(mirror);
      const Eigen::Vector3d top = h * Eigen::Vector3d(-0.16, -0.04, 0.26).cwiseProduct(mirror);
      const Eigen::Vector3d under = h * Eigen::Vector3d(-0.13, -0.20, 0.17).cwiseProduct(mirror);
      const Eigen::Vector3d forward(0, 0.3, 1), up(0, 1, 0.3), zero = Eigen::Vector3d::Zero();
      auto& w = wrist_keys_[side];
      auto& b = bend_keys_[side];
      w.push_back({0, down, zero});
      b.push_back({0, forward, zero});
      for (int k = 0; k < count_; ++k) {
        const bool on_top = (k % 2 == 0) == (side == 0);  // the left arm on top first
        for (double at : {k + 0.42, k + 0.58}) {
          w.push_back({at, on_top ? top : under, zero});
          b.push_back({at, up, zero});
        }
        const bool last = k + 1 == count_;
        w.push_back({k + 1.0, last ? down : open, zero});
        b.push_back({k + 1.0, forward, zero});
      }
    }
  }
  Pose pose_at(double t) const override {
    const double x = std::clamp((t - kRestS) / cycle_s_, 0.0, double(count_));
    Pose pose = standing();
    const auto world = forward_kinematics(s_, pose);
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector3d wrist = hermite<Eigen::Vector3d>(wrist_keys_[side], x);
      const Eigen::Vector3d bend = hermite<Eigen::Vector3d>(bend_keys_[side], x);
      solve_arm(side, world[shoulder_[side]].translation() + wrist, bend.normalized(), pose);
    }
    stand_on(pose, feet_, &mass_);
    return pose;
  }

 private:
  Foot feet_[2];
  std::vector<Key<Eigen::Vector3d>> wrist_keys_[2], bend_keys_[2];  // wrist from the shoulder
};

// Fast alternating arm swings, forward to the amplitude and back to half of it, the elbows
// bending more in front; the swing grows over the first and fades over the last 0.6 s, and the
// chest turns a little against the arms.
class ArmSwings : public Action {
 public:
  ArmSwings(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    for (int side = 0; side < 2; ++side) feet_[side] = neutral_foot(side);
    active_s_ = spec.duration_s - 2 * kRestS;
  }
  Pose pose_at(double t) const override {
    const double x = t - kRestS, ramp = std::min(0.6, 0.5 * active_s_);
    const double e = smoothstep(x / ramp) * smoothstep((active_s_ - x) / ramp);
    const double w = std::sin(2 * kPi * spec_.arm_swings.frequency_hz * x);
    const double front = spec_.arm_swings.amplitude_deg * kPi / 180, back = 0.5 * front;
    Pose pose = standing();
    for (int side = 0; side < 2; ++side) {
      const double ws = side == 0 ? w : -w;  // +1: this arm in front
      const double flexion = e * (0.5 * (back - front) - 0.5 * (front + back) * ws);
      pose.rotations[shoulder_[side]] = rot_z(sign_of(side) * 0.08) * rot_x(flexion);
      pose.rotations[elbow_[side]] = rot_x(-(0.12 + e * (0.15 + 0.2 * (1 + ws))));
    }
    rotate(pose, chest_, rot_y(-0.06 * e * w));
    stand_on(pose, feet_, &mass_);
    return pose;
  }

 private:
  Foot feet_[2];
  double active_s_ = 0;
};

// Front kicks, right leg first, then alternating: the weight shifts onto the standing foot, the
// knee comes up, the lower leg snaps out to the height asked (the ankle's highest point as a
// fraction of the hip height) with the foot pointed and the toes pulled back, returns and the
// foot goes down where it was; the trunk leans back a little against the leg.
class Kick : public Action {
 public:
  Kick(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    for (int side = 0; side < 2; ++side) {
      feet_[side] = neutral_foot(side);
      const Leg& leg = legs_[side];
      const Eigen::Vector3d hip = c(leg.hip), ankle = c(leg.ankle);
      const double chamber = 0.8 + 0.5 * spec.kick.height;  // thigh raised from vertical
      const Eigen::Vector3d knee =
          hip + leg.thigh * Eigen::Vector3d(0, -std::cos(chamber), std::sin(chamber));
      const Eigen::Vector3d tucked =
          knee + leg.shin * Eigen::Vector3d(0, -std::cos(0.4), -std::sin(0.4));
      const double drop = hip.y() - spec.kick.height * hip.y();
      const double ahead = std::sqrt(std::max(0.0, std::pow(0.9 * leg_length(), 2) - drop * drop));
      const Eigen::Vector3d top(ankle.x(), hip.y() - drop, hip.z() + ahead);
      const Eigen::Vector3d zero = Eigen::Vector3d::Zero();
      // The foot leaves the floor and comes back to it vertically, so that it does not skim it.
      const Eigen::Vector3d lifted(0, 0.1 * leg_length(), 0);
      keys_[side] = {{{0.20, zero, zero},
                      {0.27, lifted, zero},
                      {0.36, tucked - ankle, zero},
                      {0.46, top - ankle, zero},
                      {0.56, tucked - ankle, zero},
                      {0.65, lifted, zero},
                      {0.72, zero, zero}}};
    }
  }
  Pose pose_at(double t) const override {
    const Phase p = phase(t);
    const int kicker = p.index % 2 == 0 ? 1 : 0, stance = 1 - kicker;
    const double u = p.u;
    const double weight = plateau(u, 0.2);
    const double snap = smoothstep((u - 0.36) / 0.1) * smoothstep((0.56 - u) / 0.1);
    const double pointed = smoothstep((u - 0.26) / 0.08) * smoothstep((0.66 - u) / 0.08);
    Pose pose = standing();
    pose.root_position.y() -= weight * 0.02 * leg_length();
    pose.rotations[root_] = rot_x(-0.15 * snap);
    for (int side = 0; side < 2; ++side) {
      pose.rotations[shoulder_[side]] =
          rot_z(sign_of(side) * (0.1 + 0.3 * weight)) * rot_x(-0.4 * weight);
      pose.rotations[elbow_[side]] = rot_x(-0.15 - 0.9 * weight);
    }
    Foot feet[2] = {feet_[0], feet_[1]};
    feet[kicker].ankle += curve(keys_[kicker], u);
    feet[kicker].air = smoothstep((u - 0.2) / 0.05) * smoothstep((0.72 - u) / 0.05);
    Foot flat[2] = {feet_[0], feet_[1]};
    const Eigen::Vector2d centre = 0.5 * (sole_centre(0, flat[0]) + sole_centre(1, flat[1]));
    balance(mass_, pose, feet, centre + weight * (sole_centre(stance, flat[stance]) - centre));
    const Leg& leg = legs_[kicker];
    pose.rotations[leg.ankle] = pose.rotations[leg.ankle].slerp(pointed, rot_x(0.6)).normalized();
    pose.rotations[leg.ball] = pose.rotations[leg.ball].slerp(pointed, rot_x(-0.4)).normalized();
    return pose;
  }

 private:
  Foot feet_[2];
  std::array<Key<Eigen::Vector3d>, 7> keys_[2];  // the kicking ankle from where it stands
};

// Grapevine side steps: the leading foot steps out sideways, the trailing foot crosses behind
// it, the leading foot steps out again and the trailing foot crosses in front, for `count`
// cycles. A crossing foot lands a little past the other and half a foot length behind or in
// front of it, swinging round it on an arc; the pelvis turns towards the crossing leg (the
// shoulders stay square) and shifts over the standing foot while the other swings.
class SideSteps : public Action {
 public:
  SideSteps(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    dir_ = spec.side_steps.distance_m >= 0 ? 1.0 : -1.0;
    lead_ = dir_ > 0 ? 0 : 1;
    const int steps = 4 * count_;
    step_s_ = cycle_s_ / 4;
    const double advance = std::abs(spec.side_steps.distance_m) / steps;
    depth_ = 0.6 * foot_length_;
    // Uncrossed, the feet stand at least as wide as in the neutral pose; crossed, the trailing
    // foot lands the rest of two steps' advance past the leading one.
    const double open = std::max(2 * std::abs(c(legs_[0].ankle).x()), 1.4 * advance);
    // Lateral positions along the direction of travel, and depths (+ in front).
    double at[2] = {0, 0}, z[2] = {0, 0};
    at[lead_] = std::abs(c(legs_[lead_].ankle).x());
    at[1 - lead_] = -std::abs(c(legs_[1 - lead_].ankle).x());
    for (int j = 0; j < steps; ++j) {
      const int mover = j % 2 == 0 ? lead_ : 1 - lead_;
      Step st{mover, {at[mover], z[mover]}, {}, 0, 0};
      if (mover == lead_) {
        at[mover] = at[1 - mover] + open;
        z[mover] = 0;
      } else {
        at[mover] = at[1 - mover] + 2 * advance - open;
        z[mover] = (j % 4 == 1 ? -1 : 1) * depth_;
      }
      st.to = {at[mover], z[mover]};
      st.around = mover == lead_ ? 0 : (z[mover] > 0 ? 1 : -1) * 0.5 * foot_length_;
      st.yaw = mover == lead_ ? 0 : 0.5 * pelvis_yaw(z[mover]);
      steps_.push_back(st);
    }
    // The pelvis keeps one height, the highest every step reaches with soft knees.
    pelvis_y_ = stand_y_ - 0.02 * leg_length();
    double lowest = stand_y_;
    for (double t = 0; t <= spec.duration_s; t += 0.01) {
      Foot feet[2];
      Eigen::Vector3d root;
      double yaw;
      place(t, feet, &root, &yaw);
      lowest = std::min(lowest, pelvis_height(root, rot_y(yaw), feet, stand_y_));
    }
    pelvis_y_ = std::min(pelvis_y_, lowest - 0.005);
  }
  Pose pose_at(double t) const override {
    Foot feet[2];
    Eigen::Vector3d root;
    double yaw;
    place(t, feet, &root, &yaw);
    const double end = spec_.duration_s;
    Pose pose = Pose::neutral(s_);
    pose.root_position = root;
    pose.rotations[root_] = rot_y(yaw);
    const double low = smoothstep(t / kRestS) * smoothstep((end - t) / kRestS);
    pose.root_position.y() =
        pelvis_height(root, rot_y(yaw), feet, stand_y_ - (stand_y_ - pelvis_y_) * low);
    for (int j : spine_) rotate(pose, j, rot_y(-0.8 * yaw / spine_.size()));
    for (int side = 0; side < 2; ++side) {
      pose.rotations[shoulder_[side]] = rot_z(sign_of(side) * 0.3);
      pose.rotations[elbow_[side]] = rot_x(-0.4);
    }
    stand_on(pose, feet, nullptr);
    return pose;
  }

 private:
  struct Step {
    int side;
    Eigen::Vector2d from, to;  // along the travel, depth
    double around;             // how far the swing bows out in depth, signed
    double yaw;                // of the foot where it lands
  };
  // The crossing leg's depth turns the pelvis: its hip goes forward with a foot in front.
  double pelvis_yaw(double depth) const { return dir_ * 0.45 * depth / depth_; }

  void place(double t, Foot (&feet)[2], Eigen::Vector3d* root, double* yaw) const {
    const int steps = static_cast<int>(steps_.size());
    const double x = std::clamp((t - kRestS) / step_s_, 0.0, double(steps));
    const int now = std::min(steps - 1, static_cast<int>(std::floor(x)));
    const double u = x - now;
    Eigen::Vector2d where[2];
    double foot_yaw[2] = {0, 0};
    for (int side = 0; side < 2; ++side) {
      where[side] = side == lead_ ? Eigen::Vector2d(std::abs(c(legs_[side].ankle).x()), 0)
                                  : Eigen::Vector2d(-std::abs(c(legs_[side].ankle).x()), 0);
    }
    for (int j = 0; j < now; ++j) {
      where[steps_[j].side] = steps_[j].to;
      foot_yaw[steps_[j].side] = steps_[j].yaw;
    }
    const Step& st = steps_[now];
    // The foot swings during the middle 70% of its step, both feet down around it.
    // It rises before it moves and comes down vertically, so that it does not skim the floor.
    const double swing = std::clamp((u - 0.15) / 0.7, 0.0, 1.0);
    const double across = std::clamp((swing - 0.25) / 0.6, 0.0, 1.0), w = smoothstep(across);
    const Eigen::Vector2d planted = st.from + w * (st.to - st.from);
    where[st.side] = planted + Eigen::Vector2d(0, st.around * bump(across));
    const double crossing_depth = st.side == lead_ ? where[1 - lead_].y() : planted.y();
    foot_yaw[st.side] += w * (st.yaw - foot_yaw[st.side]);
    for (int side = 0; side < 2; ++side) {
      feet[side] = neutral_foot(side);
      feet[side].ankle.x() = dir_ * where[side].x();
      feet[side].ankle.z() += where[side].y();
      feet[side].yaw = foot_yaw[side];
    }
    feet[st.side].ankle.y() +=
        0.09 * leg_length() * smoothstep(swing / 0.25) * smoothstep((1 - swing) / 0.3);
    feet[st.side].air = smoothstep(swing / 0.15) * smoothstep((1 - swing) / 0.15);
    // Over the middle of the feet, leaning towards the standing one while the other swings.
    const Eigen::Vector2d middle = 0.5 * (where[0] + where[1]);
    const Eigen::Vector2d lean = 0.3 * bump(swing) * (where[1 - st.side] - where[st.side]);
    *root = Eigen::Vector3d(dir_ * (middle.x() + lean.x()), 0, c(root_).z() + middle.y());
    *yaw = pelvis_yaw(crossing_depth);
  }

  double dir_ = 1, step_s_ = 1, depth_ = 0, pelvis_y_ = 0;
  int lead_ = 0;
  std::vector<Step> steps_;
};

// Forward jumps with both feet together. Each jump: a crouch with the arms swinging back, the
// push-off with the arms swinging forward and the heels rising, the flight (the pelvis on the
// ballistic arc that rises `height`), the landing on the balls of the feet absorbed by a crouch,
// and standing up. The feet leave and meet the floor with the speed their heels give them,
// which the flight's curves take up, so no velocity jumps; the legs fold in the air.
class Jumps : public Action {
 public:
  Jumps(const ProceduralSpec& spec, const Skeleton& s) : Action(spec, s) {
    const double length = leg_length(), distance = spec.jumps.distance_m;
    for (int side = 0; side < 2; ++side) {
      flat_[side] = neutral_foot(side);
      flat_[side].ankle.y() = c(legs_[side].ankle).y();
    }
    // Standing and crouched roots, balanced over the feet.
    stand_root_ = balanced(0, 0, 0);
    crouch_root_ = balanced(kCrouch * length, kCrouchLean, kArmsBack);
    land_root_ = balanced(kCrouch * length, kCrouchLean, kArmsLanding);
    // Take-off: the legs almost straight, the hips ahead of the ankles.
    const double ahead = std::min(0.25 * distance, 0.1 * length);
    const Foot takeoff = on_ball(0, flat_[0], kTakeoffPitch);
    const double reach = 0.95 * length, along = ahead / reach;
    const Eigen::Vector3d hip =
        takeoff.ankle + reach * Eigen::Vector3d(0, std::sqrt(1 - along * along), along);
    takeoff_root_ = hip - rot_x(kTakeoffLean) * (c(legs_[0].hip) - c(root_));
    takeoff_root_.x() = 0;
    const double up = std::sqrt(2 * kGravity * spec.jumps.height_m);
    const double nominal = 2 * up / kGravity;
    velocity_ = Eigen::Vector3d(0, up, (distance - 2 * ahead) / nominal);
    // The flight ends when the hips come within 95% of the legs' length of the landing ankles.
    landing_ankle_ = on_ball(0, flat_[0], kLandingPitch).ankle + Eigen::Vector3d(0, 0, distance);
    flight_s_ = nominal;
    for (int i = 0; i < 3; ++i) {
      set_flight_keys();
      double lo = 0.5 * nominal, hi = 2 * nominal;
      for (int j = 0; j < 40; ++j) {
        const double mid = 0.5 * (lo + hi);
        const Eigen::Vector3d h =
            flight_root(mid) + rot_x(flight_lean(mid)) * (c(legs_[0].hip) - c(root_));
        ((h - landing_ankle_).norm() > reach ? lo : hi) = mid;
      }
      flight_s_ = hi;
    }
    set_flight_keys();
    // The timeline of one jump; the dynamic part has fixed lengths, crouching and standing up
    // share the rest.
    const double free = cycle_s_ - (2 * kPushS + flight_s_);
    t_crouch_ = 0.45 * free;
    t_takeoff_ = t_crouch_ + kPushS;
    t_land_ = t_takeoff_ + flight_s_;
    t_bottom_ = t_land_ + kPushS;
    t_up_ = t_bottom_ + 0.45 * free;
    const Eigen::Vector3d zero = Eigen::Vector3d::Zero(), far(0, 0, distance);
    const Eigen::Vector3d land_velocity = velocity_ - Eigen::Vector3d(0, kGravity * flight_s_, 0);
    before_ = {{{0.05 * free, stand_root_, zero},
                {t_crouch_, crouch_root_, zero},
                {t_takeoff_, takeoff_root_, velocity_}}};
    after_ = {{{t_land_, flight_root(flight_s_), land_velocity},
               {t_bottom_, land_root_ + far, zero},
               {t_up_, stand_root_ + far, zero}}};
    lean_ = {{{0.05 * free, 0, 0},
              {t_crouch_, kCrouchLean, 0},
              {t_takeoff_, kTakeoffLean, 0},
              {t_land_, kLandingLean, 0},
              {t_bottom_, kCrouchLean, 0},
              {t_up_, 0, 0}}};
    arms_ = {{{0.05 * free, 0, 0},
              {t_crouch_, kArmsBack, 0},
              {t_takeoff_ + 0.1, -2.2, 0},
              {t_land_, -1.2, 0},
              {t_bottom_, kArmsLanding, 0},
              {t_up_, 0, 0}}};
    // The ankles' velocities as the heels lift off and come down, from the feet's pitch rates.
    const auto ankle_rate = [&](double pitch, double rate) {
      return Eigen::Vector3d(
          (on_ball(0, flat_[0], pitch + 1e-6).ankle - on_ball(0, flat_[0], pitch - 1e-6).ankle) /
          2e-6 * rate);
    };
    takeoff_ankle_rate_ = ankle_rate(kTakeoffPitch, kPitchRate);
    landing_ankle_rate_ = ankle_rate(kLandingPitch, -kPitchRate);
  }

  Pose pose_at(double t) const override {
    const Phase p = phase(t);
    const double tau = p.u * cycle_s_;
    Pose pose = Pose::neutral(s_);
    const Eigen::Vector3d shift(0, 0, p.index * spec_.jumps.distance_m);
    double lean = curve(lean_, tau);
    Foot feet[2] = {flat_[0], flat_[1]};
    bool flying = false;
    if (tau < t_takeoff_) {
      pose.root_position = curve(before_, tau);
      for (int side = 0; side < 2; ++side)
        feet[side] = on_ball(side, flat_[side], hermite_pitch(tau));
    } else if (tau < t_land_) {
      flying = true;
      const double s = tau - t_takeoff_;
      pose.root_position = flight_root(s);
      lean = flight_lean(s);
    } else {
      pose.root_position = curve(after_, tau);
      for (int side = 0; side < 2; ++side) {
        feet[side].ankle.z() += spec_.jumps.distance_m;
        feet[side] = on_ball(side, feet[side], curve(landing_pitch_, tau - t_land_));
      }
    }
    pose.root_position += shift;
    pose.rotations[root_] = rot_x(lean);
    bend_trunk(pose, 0.3 * lean, 0.6 * lean);
    const double arms = curve(arms_, tau);
    for (int side = 0; side < 2; ++side) {
      pose.rotations[shoulder_[side]] = rot_z(sign_of(side) * 0.15) * rot_x(arms);
      pose.rotations[elbow_[side]] = rot_x(-0.35);
      feet[side].ankle += shift;
    }
    if (!flying) {
      stand_on(pose, feet, nullptr);
      return pose;
    }
    const double s = tau - t_takeoff_, u = s / flight_s_;
    const auto world = forward_kinematics(s_, pose);
    for (int side = 0; side < 2; ++side) {
      const Eigen::Vector3d offset = c(legs_[side].ankle) - c(legs_[0].ankle);
      const std::array<Key<Eigen::Vector3d>, 2> path = {
          {{0, on_ball(0, flat_[0], kTakeoffPitch).ankle, takeoff_ankle_rate_},
           {flight_s_, landing_ankle_, landing_ankle_rate_}}};
      const Eigen::Vector3d target =
          curve(path, s) + offset + shift + Eigen::Vector3d(0, kTuck * leg_length() * bump(u), 0);
      feet[side].ankle = within_reach(world[legs_[side].hip].translation(), target);
      feet[side].pitch = curve(flight_pitch_, s);
      feet[side].toes = bump(u);
      feet[side].air = plateau(u, 0.2);
      solve_leg(side, feet[side], pose);
    }
    return pose;
  }

 private:
  static constexpr double kCrouch = 0.22;        // root drop at the bottom, leg lengths
  static constexpr double kCrouchLean = 0.5;     // rad, pelvis forward at the bottom
  static constexpr double kTakeoffLean = 0.15;   // rad
  static constexpr double kLandingLean = 0.3;    // rad
  static constexpr double kArmsBack = 0.9;       // rad, shoulder extension in the crouch
  static constexpr double kArmsLanding = -0.8;   // rad, shoulder flexion after landing
  static constexpr double kTakeoffPitch = 0.5;   // rad, heels up as the feet leave the floor
  static constexpr double kLandingPitch = 0.35;  // rad, heels up as the balls touch down
  static constexpr double kPitchRate = 5;        // rad/s, of the heels at take-off and landing
  static constexpr double kPushS = 0.25;         // push-off and landing absorption
  static constexpr double kTuck = 0.12;          // feet drawn up mid-flight, leg lengths

  // The root balanced over the feet, crouched by `drop` with the pelvis leaning `lean` and the
  // arms at `arms`, as an offset from the first plant.
  Eigen::Vector3d balanced(double drop, double lean, double arms) const {
    Pose pose = standing();
    pose.root_position.y() -= drop;
    pose.rotations[root_] = rot_x(lean);
    bend_trunk(pose, 0.3 * lean, 0.6 * lean);
    for (int side = 0; side < 2; ++side) {
      pose.rotations[shoulder_[side]] = rot_z(sign_of(side) * 0.15) * rot_x(arms);
      pose.rotations[elbow_[side]] = rot_x(-0.35);
    }
    stand_on(pose, flat_, &mass_);
    return pose.root_position;
  }
  Eigen::Vector3d flight_root(double s) const {
    return takeoff_root_ + s * velocity_ - Eigen::Vector3d(0, 0.5 * kGravity * s * s, 0);
  }
  double flight_lean(double s) const { return curve(flight_lean_, s); }
  void set_flight_keys() {
    flight_lean_ = {
        {{0, kTakeoffLean, 0}, {0.5 * flight_s_, 0.05, 0}, {flight_s_, kLandingLean, 0}}};
    flight_pitch_ = {{{0, kTakeoffPitch, kPitchRate},
                      {0.5 * flight_s_, 0.45, 0},
                      {flight_s_, kLandingPitch, -kPitchRate}}};
    landing_pitch_ = {{{0, kLandingPitch, -kPitchRate}, {0.15, 0, 0}}};
  }
  // Heels rising through the push-off, to leave the floor turning.
  double hermite_pitch(double tau) const {
    const std::array<Key<double>, 2> keys = {
        {{t_takeoff_ - 0.2, 0, 0}, {t_takeoff_, kTakeoffPitch, kPitchRate}}};
    return curve(keys, tau);
  }
  // A swinging foot's ankle drawn towards the hip where the leg would not reach it, smoothly.
  Eigen::Vector3d within_reach(const Eigen::Vector3d& hip, const Eigen::Vector3d& target) const {
    const double soft = 0.96 * leg_length(), most = 0.99 * leg_length();
    const Eigen::Vector3d to = target - hip;
    const double d = to.norm();
    if (d <= soft) return target;
    return hip + (soft + (most - soft) * std::tanh((d - soft) / (most - soft))) / d * to;
  }

  Foot flat_[2];
  Eigen::Vector3d stand_root_, crouch_root_, land_root_, takeoff_root_, velocity_, landing_ankle_;
  Eigen::Vector3d takeoff_ankle_rate_, landing_ankle_rate_;
  double flight_s_ = 0;
  double t_crouch_ = 0, t_takeoff_ = 0, t_land_ = 0, t_bottom_ = 0, t_up_ = 0;
  std::array<Key<Eigen::Vector3d>, 3> before_, after_;
  std::array<Key<double>, 6> lean_, arms_;
  std::array<Key<double>, 3> flight_lean_, flight_pitch_;
  std::array<Key<double>, 2> landing_pitch_;
};

std::unique_ptr<Action> make_action(const ProceduralSpec& spec, const Skeleton& skeleton) {
  const std::string& k = spec.kind;
  if (k == "squat") return std::make_unique<Squat>(spec, skeleton);
  if (k == "bend_forward") return std::make_unique<BendForward>(spec, skeleton);
  if (k == "arms_cross") return std::make_unique<ArmsCross>(spec, skeleton);
  if (k == "arm_swings") return std::make_unique<ArmSwings>(spec, skeleton);
  if (k == "kick") return std::make_unique<Kick>(spec, skeleton);
  if (k == "side_steps") return std::make_unique<SideSteps>(spec, skeleton);
  if (k == "jumps") return std::make_unique<Jumps>(spec, skeleton);
  throw Error("procedural motion: '" + k + "' is not an action");
}

}  // namespace

const std::vector<std::string>& action_kinds() {
  static const std::vector<std::string> kinds = {
      "jumps", "squat", "arms_cross", "side_steps", "bend_forward", "kick", "arm_swings"};
  return kinds;
}

bool is_action(const std::string& kind) {
  const auto& k = action_kinds();
  return std::find(k.begin(), k.end(), kind) != k.end();
}

std::optional<ParameterProblem> parameter_problem(const ProceduralSpec& spec) {
  const std::string& k = spec.kind;
  std::optional<ParameterProblem> p;
  if (k == "turnaround") {
    if ((p = outside("speed", spec.speed_m_s, 0.6, 1.6, " m/s"))) return p;
    if ((p = outside("distance", spec.turnaround.distance_m, 0.1, 20, " m"))) return p;
    const double need = spec.turnaround.distance_m / spec.speed_m_s + turn_s(spec.speed_m_s);
    if (spec.duration_s < need) {
      return ParameterProblem{"duration", "must be at least " + text(need) +
                                              " s to walk the distance and turn, got " +
                                              text(spec.duration_s)};
    }
    return std::nullopt;
  }
  if (k == "arm_swings") {
    if ((p = outside("frequency", spec.arm_swings.frequency_hz, 0.2, 2.0, " Hz"))) return p;
    if ((p = outside("amplitude", spec.arm_swings.amplitude_deg, 5, 120, " deg"))) return p;
    const double need = 2 * kRestS + 1 / spec.arm_swings.frequency_hz;
    if (spec.duration_s < need) {
      return ParameterProblem{"duration", "must be at least " + text(need) +
                                              " s for one swing, got " + text(spec.duration_s)};
    }
    return std::nullopt;
  }
  if (!is_action(k)) return std::nullopt;
  const int max_count = k == "side_steps" || k == "bend_forward" ? 10 : 20;
  if ((p = outside("count", count_of(spec), 1, max_count, ""))) return p;
  if (k == "jumps") {
    if ((p = outside("distance", spec.jumps.distance_m, 0, 1.0, " m"))) return p;
    if ((p = outside("height", spec.jumps.height_m, 0.05, 0.5, " m"))) return p;
  } else if (k == "squat") {
    if ((p = outside("depth", spec.squat.depth, 0.05, 0.45, ""))) return p;
  } else if (k == "kick") {
    if ((p = outside("height", spec.kick.height, 0.2, 1.0, ""))) return p;
  } else if (k == "side_steps") {
    if ((p = outside("distance", std::abs(spec.side_steps.distance_m), 0.48 * spec.side_steps.count,
                     0.88 * spec.side_steps.count, " m (absolute value, 0.12 to 0.22 m a step)"))) {
      return p;
    }
  }
  const double need = 2 * kRestS + count_of(spec) * min_cycle_s(spec);
  if (spec.duration_s < need) {
    return ParameterProblem{"duration", "must be at least " + text(need) + " s for count " +
                                            std::to_string(count_of(spec)) + " (" +
                                            text(min_cycle_s(spec)) + " s each and " +
                                            text(kRestS) + " s standing before and after), got " +
                                            text(spec.duration_s)};
  }
  return std::nullopt;
}

std::function<Pose(double)> action_poses(const ProceduralSpec& spec, const Skeleton& skeleton) {
  if (const auto p = parameter_problem(spec)) {
    throw Error("procedural motion " + spec.kind + ": " + p->key + " " + p->message);
  }
  std::shared_ptr<const Action> action = make_action(spec, skeleton);
  return [action](double t) { return action->pose_at(t); };
}

void turnaround_path(const ProceduralSpec& spec, double t, Eigen::Vector3d* ground,
                     double* heading) {
  const double v = spec.speed_m_s, t1 = spec.turnaround.distance_m / v, turn = turn_s(v);
  const auto heading_at = [&](double x) { return kPi * smoothstep((x - t1) / turn); };
  // The walker slows to a fifth of its speed at the middle of the turn, so the turn is tight.
  const auto velocity = [&](double x) {
    const double h = heading_at(x), speed = v * (1 - 0.8 * bump((x - t1) / turn));
    return Eigen::Vector3d(speed * std::sin(h), 0, speed * std::cos(h));
  };
  // Simpson's rule over the turn up to `x`.
  const auto turned = [&](double x) {
    const int n = 64;
    const double h = (x - t1) / n;
    Eigen::Vector3d sum = velocity(t1) + velocity(x);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * velocity(t1 + i * h);
    return Eigen::Vector3d(sum * h / 3);
  };
  const Eigen::Vector3d start(0, 0, spec.turnaround.distance_m);
  *heading = heading_at(t);
  if (t <= t1) {
    *ground = Eigen::Vector3d(0, 0, v * t);
  } else if (t <= t1 + turn) {
    *ground = start + turned(t);
  } else {
    *ground = start + turned(t1 + turn) + Eigen::Vector3d(0, 0, -v * (t - t1 - turn));
  }
}

}  // namespace simcap::procedural
