// The front/back hypotheses of the monocular filter: a reflected state puts every joint on the
// reflection of its left/right partner through the vertical plane across the camera ray
// (checked joint by joint on the posed skeleton), and twice reflected is the start again.
#include <gtest/gtest.h>

#include <numbers>

#include "models/humanoid.h"
#include "tracker/gomez/body.h"
#include "tracker/gomez/body_mirror.h"

namespace simcap::tracker::gomez {
namespace {

// The joint whose name has "l_" and "r_" swapped (itself on the midline).
int partner_joint(const Skeleton& skeleton, int j) {
  const std::string& name = skeleton[j].name;
  if (!name.starts_with("l_") && !name.starts_with("r_")) return j;
  return skeleton.require((name[0] == 'l' ? "r" : "l") + name.substr(1));
}

// An asymmetric walking pose, turned and leaning, within the box.
State walking_pose(const BodyDofs& dofs) {
  State x = dofs.clamp(State::Zero(dofs.size()));
  const auto set = [&](const char* name, double v) { x[dofs.require(name)] = v; };
  set("root_tx", 0.4);
  set("root_tz", -0.7);
  set("root_turn", 0.5);
  set("root_tilt", 0.1);
  set("root_roll", -0.08);
  set("vl5_twist", 0.2);
  set("vl5_lateral", 0.05);
  set("l_shoulder_flexion", -0.7);
  set("l_shoulder_abduction", 0.4);
  set("l_elbow_flexion", -1.1);
  set("r_shoulder_flexion", 0.3);
  set("r_shoulder_twist", 0.2);
  set("r_elbow_flexion", -0.4);
  set("l_hip_flexion", -0.4);
  set("r_hip_flexion", 0.25);
  set("l_knee_flexion", 0.6);
  return dofs.clamp(x);
}

class BodyMirrorTest : public ::testing::TestWithParam<bool> {};

TEST_P(BodyMirrorTest, ReflectsEveryJointOntoItsPartner) {
  const Skeleton skeleton = build_humanoid();
  const Body body(skeleton, BodyKind::full, Pose::neutral(skeleton), GetParam());
  const BodyMirror mirror(body.dofs);
  ASSERT_TRUE(mirror.available());
  const State x = walking_pose(body.dofs);
  const Eigen::Vector3d camera(2.0, 1.6, 3.5);
  const State y = mirror.reflect(x, camera);
  const auto before = joint_positions(body.skeleton, body.dofs.pose(x));
  const auto after = joint_positions(body.skeleton, body.dofs.pose(y));
  // The plane through the root whose normal is the horizontal part of the ray to it.
  const Eigen::Vector3d root = before[0];
  Eigen::Vector3d n = root - camera;
  n.y() = 0;
  n.normalize();
  for (int j = 0; j < body.skeleton.size(); ++j) {
    const Eigen::Vector3d d = before[j] - root;
    const Eigen::Vector3d reflected = root + d - 2 * n.dot(d) * n;
    EXPECT_LT((after[partner_joint(body.skeleton, j)] - reflected).norm(), 1e-9)
        << body.skeleton[j].name;
  }
  // Reflecting again brings the start back (the root stays, so the plane is the same).
  EXPECT_LT((mirror.reflect(y, camera) - x).cwiseAbs().maxCoeff(), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Floor, BodyMirrorTest, ::testing::Bool());

TEST(BodyMirror, UpperBodyHasNoRootToTurn) {
  const Skeleton skeleton = build_humanoid();
  const Body body(skeleton, BodyKind::upper, Pose::neutral(skeleton), false);
  const BodyMirror mirror(body.dofs);
  EXPECT_FALSE(mirror.available());
  const State x = body.dofs.clamp(State::Zero(body.dofs.size()));
  EXPECT_EQ(mirror.reflect(x, Eigen::Vector3d(0, 1.5, 3)), x);
}

}  // namespace
}  // namespace simcap::tracker::gomez
