// The canonical skeleton: H-Anim names and hierarchy, proportions, forward kinematics.
#include <gtest/gtest.h>

#include <numbers>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/pose.h"

namespace simcap {
namespace {

TEST(Humanoid, HasTheHAnimJointsAndHierarchy) {
  const Skeleton s = build_humanoid();
  for (const char* name : {"humanoid_root", "sacroiliac",
                           "l_hip",         "r_knee",
                           "l_talocrural",  "vl5",
                           "vl3",           "vl1",
                           "vt10",          "vt6",
                           "vt1",           "vc7",
                           "skullbase",     "l_sternoclavicular",
                           "r_shoulder",    "l_elbow",
                           "r_radiocarpal", "l_metatarsophalangeal_2",
                           "skull_tip",     "l_hand_tip",
                           "r_toe_tip"}) {
    EXPECT_GE(s.find(name), 0) << name;
  }
  EXPECT_EQ(s[s.require("l_knee")].parent, s.require("l_hip"));
  EXPECT_EQ(s[s.require("l_hip")].parent, s.require("sacroiliac"));
  EXPECT_EQ(s[s.require("l_shoulder")].parent, s.require("l_sternoclavicular"));
  EXPECT_EQ(s[s.require("l_knee")].segment, "l_calf");
  EXPECT_TRUE(s.is_descendant(s.require("r_hand_tip"), s.require("vl5")));
  EXPECT_FALSE(s.is_descendant(s.require("r_hand_tip"), s.require("sacroiliac")));
  for (int j = 1; j < s.size(); ++j) EXPECT_LT(s[j].parent, j);
  for (const auto& name : he15_joints()) EXPECT_GE(s.find(name), 0) << name;
  EXPECT_THROW(s.require("l_wing"), Error);
}

TEST(Humanoid, ProportionsFollowHeightAndFaceForward) {
  for (double H : {1.5, 1.75, 1.95}) {
    const Skeleton s = build_humanoid({.height = H, .proportions = {}});
    auto c = [&](const char* n) { return s[s.require(n)].center; };
    EXPECT_NEAR(c("skull_tip").y(), H, 1e-12);
    EXPECT_NEAR((c("l_elbow") - c("l_shoulder")).norm(), 0.186 * H, 0.01 * H);
    EXPECT_NEAR((c("l_knee") - c("l_hip")).norm(), 0.245 * H, 0.01 * H);
    EXPECT_GT(c("l_hip").x(), 0);  // +X is the humanoid's left
    EXPECT_LT(c("r_shoulder").x(), 0);
    EXPECT_GT(c("l_toe_tip").z(), c("l_talocrural").z());  // faces +Z
    EXPECT_GE(c("l_toe_tip").y(), 0);
  }
  EXPECT_THROW(build_humanoid({.height = 0.1, .proportions = {}}), Error);
}

// A scene's actors[i].height takes [0.5, 2.5] m, both ends included: both build.
TEST(Humanoid, BuildsTheSceneHeightsEndsIncluded) {
  for (double H : {0.5, 2.5}) {
    const Skeleton s = build_humanoid({.height = H, .proportions = {}});
    EXPECT_NEAR(s[s.require("skull_tip")].center.y(), H, 1e-12);
  }
}

TEST(Humanoid, ShoulderRiseLiftsTheArmsAndKeepsTheTrunk) {
  const Skeleton plain = build_humanoid();
  BodyParameters shrugged;
  shrugged.proportions.shoulder_rise = 0.04;
  const Skeleton s = build_humanoid(shrugged);
  auto rise = [&](const char* n) {
    return s[s.require(n)].center.y() - plain[plain.require(n)].center.y();
  };
  for (const char* arm : {"l_shoulder", "r_elbow", "l_radiocarpal", "r_hand_tip"})
    EXPECT_NEAR(rise(arm), 0.04 * 1.75, 1e-12) << arm;
  for (const char* trunk : {"vc7", "l_sternoclavicular", "l_hip", "skull_tip"})
    EXPECT_EQ(rise(trunk), 0) << trunk;
  EXPECT_NEAR(
      (s[s.require("l_elbow")].center - s[s.require("l_shoulder")].center).norm(),
      (plain[plain.require("l_elbow")].center - plain[plain.require("l_shoulder")].center).norm(),
      1e-12);
}

TEST(ForwardKinematics, NeutralPoseGivesTheCentres) {
  const Skeleton s = build_humanoid();
  const auto p = joint_positions(s, Pose::neutral(s));
  for (int j = 0; j < s.size(); ++j) EXPECT_LT((p[j] - s[j].center).norm(), 1e-12);
}

TEST(ForwardKinematics, ElbowFlexionMovesOnlyTheForearmChain) {
  const Skeleton s = build_humanoid();
  Pose pose = Pose::neutral(s);
  const int elbow = s.require("l_elbow");
  pose.rotations[elbow] = Eigen::AngleAxisd(-std::numbers::pi / 2, Eigen::Vector3d::UnitX());
  const auto p = joint_positions(s, pose);
  for (int j = 0; j < s.size(); ++j) {
    if (!s.is_descendant(j, elbow) || j == elbow) {
      EXPECT_LT((p[j] - s[j].center).norm(), 1e-12);
    }
  }
  // The forearm keeps its length and, flexed by 90 degrees (a negative rotation about +X, the
  // humanoid's left), points forward (+Z).
  const int wrist = s.require("l_radiocarpal");
  const Eigen::Vector3d forearm = p[wrist] - p[elbow];
  EXPECT_NEAR(forearm.norm(), s.offset(wrist).norm(), 1e-12);
  EXPECT_GT(forearm.z(), 0.9 * forearm.norm());
}

TEST(ForwardKinematics, RootTranslationMovesEverything) {
  const Skeleton s = build_humanoid();
  Pose pose = Pose::neutral(s);
  const Eigen::Vector3d shift(0.3, -0.1, 2.0);
  pose.root_position += shift;
  const auto p = joint_positions(s, pose);
  for (int j = 0; j < s.size(); ++j) EXPECT_LT((p[j] - s[j].center - shift).norm(), 1e-12);
  pose.rotations.pop_back();
  EXPECT_THROW(forward_kinematics(s, pose), Error);
}

}  // namespace
}  // namespace simcap
