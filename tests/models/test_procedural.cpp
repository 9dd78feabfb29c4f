// Procedural motions: deterministic, parameterised, feet on the floor without sliding, legs
// alternating and arms swinging against them, paths and turns as asked.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/foot_contact.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"
#include "models/motion_source.h"
#include "models/pose.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;

Motion make(const std::string& kind, double duration = 4.0, double fps = 30.0) {
  ProceduralSpec spec;
  spec.kind = kind;
  spec.duration_s = duration;
  return generate_procedural(spec, build_humanoid(), fps);
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  double ma = 0, mb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ma += a[i] / a.size();
    mb += b[i] / b.size();
  }
  double ab = 0, aa = 0, bb = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(aa * bb);
}

TEST(Procedural, EveryKindIsDeterministicWithTheRequestedLength) {
  const Skeleton s = build_humanoid();
  for (const auto& kind : procedural_kinds()) {
    const Motion a = make(kind, 6.0, 10.0);
    const Motion b = make(kind, 6.0, 10.0);
    // The gesture corpus has its own length (models/gesture_motion.h).
    if (kind != "gestures") {
      ASSERT_EQ(a.frames.size(), 61u) << kind;
    }
    ASSERT_EQ(a.frames.size(), b.frames.size()) << kind;
    EXPECT_DOUBLE_EQ(a.fps, 10.0);
    for (size_t f = 0; f < a.frames.size(); ++f) {
      EXPECT_EQ(a.frames[f].root_position, b.frames[f].root_position) << kind;
      for (int j = 0; j < s.size(); ++j) {
        EXPECT_EQ(a.frames[f].rotations[j].coeffs(), b.frames[f].rotations[j].coeffs()) << kind;
      }
    }
  }
}

TEST(Procedural, FeetStayOnTheFloorWithoutSliding) {
  const Skeleton s = build_humanoid();
  // The actions, jumps among them, have their own checks (test_procedural_actions.cpp).
  for (const char* kind : {"stand", "tpose", "walk_in_place", "walk_path", "arm_raise", "turn"}) {
    const FootStats feet = measure_feet(humanoid_feet(s, make(kind, 6.0)));
    // Some foot is always down: the lowest sole point is on the floor in every frame.
    EXPECT_GT(feet.lowest_min, -1e-6) << kind;
    EXPECT_LT(feet.lowest_mean, 1e-6) << kind;
    // Planted feet only roll about the ball as the heel rises (under 1.5 cm per step).
    EXPECT_LT(feet.drift_max, 0.015) << kind;
    EXPECT_LT(feet.slide_median, 1e-6) << kind;
    EXPECT_GT(feet.contacts, 0) << kind;
  }
}

TEST(Procedural, WalkingAlternatesLegsAndSwingsArmsAgainstThem) {
  const Skeleton s = build_humanoid();
  const int root = s.require("humanoid_root");
  const int ankle[2] = {s.require("l_talocrural"), s.require("r_talocrural")};
  const int wrist[2] = {s.require("l_radiocarpal"), s.require("r_radiocarpal")};
  for (const char* kind : {"walk_path", "walk_in_place"}) {
    const Motion m = make(kind, 4.0, 60.0);
    const FootTrack soles = humanoid_feet(s, m);
    std::vector<double> foot_ahead[2], hand_ahead[2];
    int both_up = 0, up[2] = {0, 0};
    for (size_t f = 0; f < m.frames.size(); ++f) {
      const auto world = forward_kinematics(s, m.frames[f]);
      // Forward is the pelvis' heading; "ahead" is measured from the pelvis along it.
      Eigen::Vector3d forward = world[root].linear() * Eigen::Vector3d::UnitZ();
      forward.y() = 0;
      forward.normalize();
      bool lifted[2];
      for (int side = 0; side < 2; ++side) {
        double low = INFINITY;
        for (const auto& p : soles.frames[f][side]) low = std::min(low, p.y());
        lifted[side] = low > 0.01;
        up[side] += lifted[side];
        const Eigen::Vector3d p = world[root].translation();
        foot_ahead[side].push_back((world[ankle[side]].translation() - p).dot(forward));
        hand_ahead[side].push_back((world[wrist[side]].translation() - p).dot(forward));
      }
      both_up += lifted[0] && lifted[1];
    }
    EXPECT_EQ(both_up, 0) << kind;  // walking, not running or hopping
    EXPECT_GT(up[0], 20) << kind;
    EXPECT_GT(up[1], 20) << kind;
    if (std::string(kind) == "walk_path") {
      // The left foot goes forward while the right goes back, and the left arm with the right foot.
      EXPECT_LT(correlation(foot_ahead[0], foot_ahead[1]), -0.8);
      EXPECT_LT(correlation(foot_ahead[0], hand_ahead[0]), -0.8);
      EXPECT_GT(correlation(foot_ahead[1], hand_ahead[0]), 0.8);
    } else {
      EXPECT_LT(correlation(hand_ahead[0], hand_ahead[1]), -0.8);
    }
  }
}

TEST(Procedural, WalkPathFollowsItsCircleAtItsSpeed) {
  ProceduralSpec spec;
  spec.kind = "walk_path";
  spec.duration_s = 5.0;
  spec.speed_m_s = 1.0;
  spec.path_radius = 2.0;
  const Skeleton s = build_humanoid();
  const Motion m = generate_procedural(spec, s, 30.0);
  const Eigen::Vector3d centre(2.0, 0, 0);
  for (const Pose& pose : m.frames) {
    Eigen::Vector3d p = pose.root_position - centre;
    p.y() = 0;
    EXPECT_NEAR(p.norm(), 2.0, 0.03);  // lateral sway only
  }
  // 5 m of arc on a 2 m circle: 2.5 rad from the start at the origin.
  const double a = 2.5;
  const Eigen::Vector3d end = centre + 2.0 * Eigen::Vector3d(-std::cos(a), 0, std::sin(a));
  Eigen::Vector3d d = m.frames.back().root_position - end;
  d.y() = 0;
  EXPECT_LT(d.norm(), 0.03);
}

TEST(Procedural, TurnEndsFacingTheNewDirection) {
  ProceduralSpec spec;
  spec.kind = "turn";
  spec.duration_s = 3.0;
  spec.turn_degrees = 90.0;
  const Skeleton s = build_humanoid();
  const Motion m = generate_procedural(spec, s, 30.0);
  const Eigen::Vector3d forward =
      m.frames.back().rotations[s.require("humanoid_root")] * Eigen::Vector3d::UnitZ();
  EXPECT_LT((forward - Eigen::Vector3d(1, 0, 0)).norm(), 1e-9);  // +Z turned left to +X
  const Eigen::Vector3d p = m.frames.back().root_position;
  EXPECT_LT(std::hypot(p.x(), p.z()), 0.03);  // on the spot, give or take the sway
}

TEST(Procedural, ArmPoses) {
  const Skeleton s = build_humanoid();
  const int shoulder = s.require("l_shoulder"), elbow = s.require("l_elbow");
  const int hand_tip = s.require("r_hand_tip"), head = s.require("skull_tip");
  const auto t = joint_positions(s, make("tpose", 0.0).frames[0]);
  EXPECT_EQ(make("tpose", 0.0).frames.size(), 1u);
  const Eigen::Vector3d arm = (t[elbow] - t[shoulder]).normalized();
  EXPECT_GT(arm.x(), std::cos(5 * kPi / 180));  // horizontal, pointing left
  const Motion raise = make("arm_raise", 4.0);
  const auto top = joint_positions(s, raise.frames[60]);      // half way: arms up
  const auto bottom = joint_positions(s, raise.frames[120]);  // the end: down again
  EXPECT_GT(top[hand_tip].y(), top[head].y());
  EXPECT_LT(bottom[hand_tip].y(), s[s.require("r_hip")].center.y());
}

// The gestures stay within Gomez Jauregui's Table 2-1 (so that his upper body can follow them),
// start and end with the arms hanging, and move the hands where the thesis's sequences do:
// "raise" in the frontal plane, "ask" along the depth.
TEST(Procedural, ArmGestures) {
  const Skeleton s = build_humanoid();
  const int wrist = s.require("l_radiocarpal"), chest = s.require("vt1");
  double frontal[2] = {0, 0}, depth[2] = {0, 0};
  for (const std::string& g : gesture_names()) {
    ProceduralSpec spec;
    spec.kind = "arm_gesture";
    spec.gesture = g;
    spec.duration_s = 5.5;
    const Motion m = generate_procedural(spec, s, 30.0);
    ASSERT_EQ(m.frames.size(), 166u);
    for (const Pose& p : m.frames) {
      for (const JointLimits& j : gomez_joint_limits()) {
        if (j.joint == "vl5" || j.joint == "skullbase" || j.joint.ends_with("radiocarpal"))
          continue;
        // Z-X-Y angles with X in [-pi/2, pi/2], or the other solution (a + pi, -pi - b,
        // c + pi) when the flexion passes 90 degrees.
        const auto angles = dof_angles(j, p.rotations[s.require(j.joint)]);
        std::vector<double> other = angles;
        if (other.size() == 3) {
          other = {std::remainder(angles[0] + kPi, 2 * kPi), -kPi - angles[1],
                   std::remainder(angles[2] + kPi, 2 * kPi)};
        }
        const auto inside = [&](const std::vector<double>& a) {
          for (size_t d = 0; d < a.size(); ++d) {
            if (a[d] < j.dofs[d].lower - 1e-9 || a[d] > j.dofs[d].upper + 1e-9) return false;
          }
          return true;
        };
        EXPECT_TRUE(inside(angles) || inside(other)) << g << " " << j.joint;
      }
    }
    const auto first = joint_positions(s, m.frames.front());
    const auto last = joint_positions(s, m.frames.back());
    EXPECT_LT((first[wrist] - last[wrist]).norm(), 0.02) << g;
    double fr = 0, dz = 0;
    for (const Pose& p : m.frames) {
      const auto q = joint_positions(s, p);
      const Eigen::Vector3d d = q[wrist] - q[chest] - (first[wrist] - first[chest]);
      fr = std::max(fr, std::hypot(d.x(), d.y()));
      dz = std::max(dz, std::abs(d.z()));
    }
    if (g == "raise") {
      frontal[0] = fr;
      depth[0] = dz;
    }
    if (g == "ask") {
      frontal[1] = fr;
      depth[1] = dz;
    }
  }
  EXPECT_GT(frontal[0], 2 * depth[0]);  // raise: in the image plane of a camera in front
  EXPECT_GT(depth[1], 0.4);             // ask: the hands go forward by 40 cm or more
  ProceduralSpec bad;
  bad.kind = "arm_gesture";
  bad.gesture = "shrug";
  EXPECT_THROW(generate_procedural(bad, s, 30), Error);
}

TEST(Procedural, BadSpecsAreErrors) {
  const Skeleton s = build_humanoid();
  ProceduralSpec spec;
  spec.kind = "moonwalk";
  try {
    generate_procedural(spec, s, 30);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("walk_in_place"), std::string::npos) << e.what();
  }
  spec.kind = "walk_path";
  EXPECT_THROW(generate_procedural(spec, s, 0), Error);
  spec.path_radius = 0;
  EXPECT_THROW(generate_procedural(spec, s, 30), Error);
  spec = {};
  spec.duration_s = -1;
  EXPECT_THROW(generate_procedural(spec, s, 30), Error);
  Skeleton legless;
  legless.add({"humanoid_root", "sacrum", -1, {0, 1, 0}, false});
  EXPECT_THROW(generate_procedural({}, legless, 30), Error);
}

}  // namespace
}  // namespace simcap
