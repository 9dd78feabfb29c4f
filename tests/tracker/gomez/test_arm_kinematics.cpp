// The body's state <-> pose conversions and the arms' analytic kinematics: state_of inverts pose,
// kinematic flipping (H4) keeps the elbows' and wrists' projections while moving them in depth,
// and the end-effector IK (H5) puts the wrist where it is asked; H2 diffuses the root with the
// legs.
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "core/camera.h"
#include "models/humanoid.h"
#include "tracker/gomez/body.h"
#include "tracker/gomez/particle_filter.h"

namespace simcap::tracker::gomez {
namespace {

// A body facing a camera 3 m in front of it, arms bent forward within Table 2-1.
struct Scene {
  Skeleton skeleton = build_humanoid();
  Body body{skeleton, BodyKind::full, Pose::neutral(skeleton), false};
  Camera camera = Camera::look_at("cam", 640, 480, std::numbers::pi / 3,
                                  Eigen::Vector3d(0.3, 1.5, 3.0), Eigen::Vector3d(0, 1.1, 0));
  State x;
  Scene() {
    x = body.dofs.clamp(State::Zero(body.dofs.size()));
    const auto set = [&](const char* name, double v) { x[body.dofs.require(name)] = v; };
    set("l_shoulder_flexion", -0.7);
    set("l_shoulder_abduction", 0.4);
    set("l_elbow_flexion", -1.1);
    set("r_shoulder_flexion", -0.5);
    set("r_shoulder_abduction", -0.3);
    set("r_elbow_flexion", -0.9);
    x = body.dofs.clamp(x);
  }
  Eigen::Vector3d joint(const State& s, const char* name) const {
    return joint_positions(body.skeleton, body.dofs.pose(s))[body.skeleton.require(name)];
  }
};

TEST(BodyDofs, StateOfInvertsPose) {
  const Scene s;
  State y = s.x;
  y[s.body.dofs.require("l_shoulder_twist")] = 0.2;
  y[s.body.dofs.require("r_radiocarpal_twist")] = -0.4;
  y[s.body.dofs.require("root_turn")] += 0.3;
  y = s.body.dofs.clamp(y);
  const State back = s.body.dofs.state_of(s.body.dofs.pose(y), s.x);
  EXPECT_LT((back - y).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(BodyDofs, H2DiffusesTheRootWithTheLegs) {
  const Scene s;
  const BodyDofs& dofs = s.body.dofs;
  const auto diffused = [&](std::initializer_list<Part> parts) {
    std::array<bool, kPartCount> moved{};
    for (const Part p : parts) moved[static_cast<int>(p)] = true;
    std::vector<std::string> names;
    for (const Dof& d : dofs.dofs()) {
      if (h2_diffuses(d, moved)) names.push_back(d.name);
    }
    return names;
  };
  const auto has = [](const std::vector<std::string>& names, const char* name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  const auto arm = diffused({Part::left_arm});
  EXPECT_TRUE(has(arm, "l_elbow_flexion"));
  EXPECT_FALSE(has(arm, "root_tx"));
  EXPECT_FALSE(has(arm, "r_elbow_flexion"));
  const auto leg = diffused({Part::right_leg});
  EXPECT_TRUE(has(leg, "root_tx"));
  EXPECT_TRUE(has(leg, "root_tz"));
  EXPECT_FALSE(has(leg, "root_turn"));
  EXPECT_FALSE(has(leg, "l_knee_flexion"));
  EXPECT_TRUE(has(diffused({Part::torso}), "root_turn"));
  EXPECT_TRUE(diffused({}).empty());
}

TEST(ArmKinematics, FlippingKeepsTheProjectionsAndMovesInDepth) {
  const Scene s;
  const Eigen::Vector3d c = s.camera.centre();
  const std::vector<State> flips = s.body.arms.flips(s.x, c);
  ASSERT_FALSE(flips.empty());
  EXPECT_LE(flips.size(), 15u);
  int moved = 0;
  for (const State& y : flips) {
    EXPECT_TRUE(s.body.dofs.inside(y, 1e-6));
    for (const char* name : {"l_elbow", "l_radiocarpal", "r_elbow", "r_radiocarpal"}) {
      const Eigen::Vector3d before = s.joint(s.x, name), after = s.joint(y, name);
      EXPECT_LT((*s.camera.project(before) - *s.camera.project(after)).norm(), 1e-6) << name;
      if ((after - c).norm() - (before - c).norm() > 0.01) ++moved;
      if ((after - c).norm() - (before - c).norm() < -0.01) ++moved;
    }
    // The limbs keep their lengths: the shoulders do not move.
    EXPECT_LT((s.joint(y, "l_shoulder") - s.joint(s.x, "l_shoulder")).norm(), 1e-9);
  }
  EXPECT_GE(moved, static_cast<int>(flips.size()));
}

TEST(ArmKinematics, EndEffectorSolvePutsTheWristWhereAsked) {
  const Scene s;
  for (int side = 0; side < 2; ++side) {
    const ArmPoints a = s.body.arms.points(s.x, side);
    // A wrist target 6 cm away, the elbow on its swivel circle at the current swivel.
    const Eigen::Vector3d target = a.wrist + Eigen::Vector3d(0.03, 0.04, -0.03);
    const auto elbow = s.body.arms.swivel_elbow(a, target, s.body.arms.swivel(a));
    ASSERT_TRUE(elbow);
    State y = s.x;
    ASSERT_TRUE(s.body.arms.solve(y, side, *elbow, target));
    const ArmPoints b = s.body.arms.points(y, side);
    EXPECT_LT((b.wrist - target).norm(), 1e-6);
    EXPECT_LT((b.elbow - *elbow).norm(), 1e-6);
  }
}

// H5 from the image: every proposal puts the hand's far end (the foot's toe, for the legs'
// kinematics) on the asked pixel (to well under a pixel), at depths spread along its camera ray,
// within the limits, the shoulders and hips unmoved.
TEST(ArmKinematics, ReachingARayPutsTheHandOnItsPixelAtSeveralDepths) {
  const Scene s;
  ASSERT_TRUE(s.body.legs.has_value());
  for (const bool legs : {false, true}) {
    const ArmKinematics& limbs = legs ? *s.body.legs : s.body.arms;
    for (int side = 0; side < 2; ++side) {
      const std::string end =
          std::string(side == 0 ? "l_" : "r_") + (legs ? "talocrural" : "radiocarpal");
      const Capsule* hand = nullptr;
      for (const Capsule& c : s.body.shape.capsules) {
        if (s.body.skeleton[c.joint].name == end) hand = &c;
      }
      ASSERT_NE(hand, nullptr);
      const auto tip_of = [&](const State& y) {
        return forward_kinematics(s.body.skeleton, s.body.dofs.pose(y))[hand->joint] * hand->b;
      };
      // A pixel 30 px beside the end's present projection and 25 px higher.
      const Eigen::Vector2d pixel = *s.camera.project(tip_of(s.x)) + Eigen::Vector2d(30, -25);
      const Eigen::Vector3d c = s.camera.centre(), ray = s.camera.unproject(pixel);
      const std::vector<State> poses = limbs.reach_ray(s.x, side, hand->b, c, ray, 4);
      ASSERT_GE(poses.size(), 3u) << end;
      double nearest = INFINITY, farthest = 0;
      for (const State& y : poses) {
        EXPECT_TRUE(s.body.dofs.inside(y, 1e-6));
        const Eigen::Vector3d tip = tip_of(y);
        EXPECT_LT((*s.camera.project(tip) - pixel).norm(), 0.1) << end;
        nearest = std::min(nearest, (tip - c).norm());
        farthest = std::max(farthest, (tip - c).norm());
        for (const char* root : {"l_shoulder", "r_shoulder", "l_hip", "r_hip"}) {
          EXPECT_LT((s.joint(y, root) - s.joint(s.x, root)).norm(), 1e-9) << end << root;
        }
      }
      EXPECT_GT(farthest - nearest, 0.2) << end;
    }
  }
  // A ray the arm cannot reach (far above the body) gives none.
  const Eigen::Vector3d up = (Eigen::Vector3d(0, 4, 0) - s.camera.centre()).normalized();
  EXPECT_TRUE(
      s.body.arms.reach_ray(s.x, 0, Eigen::Vector3d::Zero(), s.camera.centre(), up, 4).empty());
}

}  // namespace
}  // namespace simcap::tracker::gomez
