// The body's centre of mass against anthropometry: its standing height as a fraction of stature,
// the left-right symmetry, and a limb moving the centre by its own mass fraction.
#include <gtest/gtest.h>

#include "core/error.h"
#include "models/body_mass.h"
#include "models/humanoid.h"
#include "models/pose.h"

namespace simcap {
namespace {

TEST(BodyMass, StandingCentreLiesAtAbout56PercentOfStature) {
  // Adults' standing centre of mass lies at 55-57% of their height (Winter 2009, sec. 4.1; Le
  // Veau, "Biomechanics of human motion": 55% women, 56-57% men).
  for (const double height : {1.5, 1.75, 2.0}) {
    const Skeleton s = build_humanoid({.height = height, .proportions = {}});
    const Eigen::Vector3d com = BodyMass(s).center(joint_positions(s, Pose::neutral(s)));
    EXPECT_NEAR(com.y() / height, 0.56, 0.015) << height;
    EXPECT_NEAR(com.x(), 0.0, 1e-12) << height;
    EXPECT_NEAR(com.z(), 0.0, 0.02 * height) << height;
  }
}

TEST(BodyMass, AnArmMovesTheCentreByItsShareOfTheMass) {
  const Skeleton s = build_humanoid();
  const BodyMass mass(s);
  const Pose neutral = Pose::neutral(s);
  Pose raised = neutral;
  raised.rotations[s.require("l_shoulder")] =
      Eigen::Quaterniond(Eigen::AngleAxisd(-EIGEN_PI / 2, Eigen::Vector3d::UnitX()));
  const auto p0 = joint_positions(s, neutral), p1 = joint_positions(s, raised);
  // The arm's own centre (upper arm, forearm, hand: 5% of the body) moves; the rest stays.
  const Eigen::Vector3d moved = mass.center(p1) - mass.center(p0);
  const int shoulder = s.require("l_shoulder"), elbow = s.require("l_elbow"),
            wrist = s.require("l_radiocarpal"), tip = s.require("l_hand_tip");
  const auto arm_centre = [&](const std::vector<Eigen::Vector3d>& p) {
    const Eigen::Vector3d knuckles = p[wrist] + 0.45 * (p[tip] - p[wrist]);
    return Eigen::Vector3d(0.028 * (p[shoulder] + 0.436 * (p[elbow] - p[shoulder])) +
                           0.016 * (p[elbow] + 0.430 * (p[wrist] - p[elbow])) +
                           0.006 * (p[wrist] + 0.506 * (knuckles - p[wrist])));
  };
  EXPECT_LT((moved - (arm_centre(p1) - arm_centre(p0))).norm(), 1e-12);
  EXPECT_GT(moved.z(), 0.01);  // forward
}

TEST(BodyMass, NeedsTheHumanoidsJoints) {
  Skeleton s;
  s.add({"humanoid_root", "sacrum", -1, {0, 1, 0}, false});
  EXPECT_THROW(BodyMass{s}, Error);
}

}  // namespace
}  // namespace simcap
