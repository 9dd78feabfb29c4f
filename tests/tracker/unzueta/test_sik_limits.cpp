// SIK's biomechanical limits: the swing cone spline (thesis eq. 10) and the swing-twist-hinge
// clamping on the canonical humanoid, checked against anatomical directions.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "core/error.h"
#include "models/humanoid.h"
#include "tracker/unzueta/sik_limits.h"
#include "tracker/unzueta/sik_swing_cone.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double deg(double d) {
  return d * kPi / 180.0;
}

TEST(SikSwingCone, PassesThroughItsPointsWithEqualEndSlopes) {
  const std::vector<std::pair<double, double>> points = {
      {-kPi, 0.5}, {-kPi / 2, 0.3}, {0.0, 1.4}, {kPi / 2, 0.8}, {kPi, 0.5}};
  const SwingCone cone(points);
  for (const auto& [theta, psi] : points) EXPECT_NEAR(cone.max_swing(theta), psi, 1e-12);
  // Eq. 10: both end slopes are the mean of the first and last secants.
  const double h = 1e-6;
  const double expected = 0.5 * ((0.3 - 0.5) / (kPi / 2) + (0.5 - 0.8) / (kPi / 2));
  EXPECT_NEAR((cone.max_swing(-kPi + h) - cone.max_swing(-kPi)) / h, expected, 1e-5);
  EXPECT_NEAR((cone.max_swing(kPi) - cone.max_swing(kPi - h)) / h, expected, 1e-5);
  // Theta wraps around.
  EXPECT_NEAR(cone.max_swing(0.3 + 2 * kPi), cone.max_swing(0.3), 1e-12);
}

TEST(SikSwingCone, RejectsBadPoints) {
  EXPECT_THROW(SwingCone({{-kPi, 0.5}, {kPi, 0.5}}), Error);
  EXPECT_THROW(SwingCone({{-kPi, 0.5}, {0.0, 1.0}, {kPi, 0.6}}), Error);  // ends differ
  EXPECT_THROW(SwingCone({{-kPi, 0.5}, {0.5, 1.0}, {0.2, 1.0}, {kPi, 0.5}}), Error);
  EXPECT_THROW(SwingCone({{-kPi, 0.5}, {0.0, 4.0}, {kPi, 0.5}}), Error);  // psi beyond pi
  EXPECT_THROW(SwingCone({{-3.0, 0.5}, {0.0, 1.0}, {kPi, 0.5}}), Error);  // does not start at -pi
}

class SikLimitsTest : public ::testing::Test {
 protected:
  SikBody body{build_humanoid()};
  SikLimits limits{body};
  int joint(const char* name) const { return body.skeleton().require(name); }
};

TEST_F(SikLimitsTest, ClampedRotationsAreWithinTheLimitsAndInsideOnesAreKept) {
  std::mt19937 rng(7);
  std::normal_distribution<double> gauss;
  for (int j = 0; j < body.size(); ++j) {
    for (int i = 0; i < 200; ++i) {
      const Eigen::Quaterniond q =
          Eigen::Quaterniond(gauss(rng), gauss(rng), gauss(rng), gauss(rng)).normalized();
      const Eigen::Quaterniond c = limits.clamp(j, q);
      EXPECT_LT(limits.excess(j, c), 1e-9) << body.skeleton()[j].name;
      // Clamping is idempotent.
      EXPECT_LT(c.angularDistance(limits.clamp(j, c)), 1e-9) << body.skeleton()[j].name;
      if (limits.excess(j, q) == 0.0) {
        EXPECT_LT(q.angularDistance(c), 1e-12);
      }
    }
  }
}

TEST_F(SikLimitsTest, ShoulderFollowsTheClinicalRanges) {
  const int l = joint("l_shoulder");
  // Flexion (arm forward and up) 150 degrees is inside; extension (backward) 80 is pulled back
  // to 60 in the same plane.
  const Eigen::Quaterniond flexion(Eigen::AngleAxisd(-deg(150), Eigen::Vector3d::UnitX()));
  EXPECT_EQ(limits.excess(l, flexion), 0.0);
  const Eigen::Quaterniond extension(Eigen::AngleAxisd(deg(80), Eigen::Vector3d::UnitX()));
  EXPECT_NEAR(limits.excess(l, extension), deg(20), deg(1));
  // Pulled back along its meridian: in the plane of the neutral and the requested directions.
  const Eigen::Vector3d pole = body.segment_direction(l);
  const Eigen::Vector3d arm = limits.clamp(l, extension) * pole;
  const SwingTwist st = limits.decompose(l, limits.clamp(l, extension));
  EXPECT_NEAR(st.psi, limits.max_swing(l, st.theta), 1e-9);  // on the cone
  EXPECT_NEAR(st.psi, deg(60), deg(1));
  EXPECT_NEAR(arm.dot(pole.cross(extension * pole).normalized()), 0.0, 1e-9);
  EXPECT_LT(arm.z(), 0.0);  // still backward

  // Internal rotation turns a forearm bent 90 degrees forward toward the midline: 80 degrees is
  // clamped to 70 on either side, 80 of external rotation is kept.
  for (const char* name : {"l_shoulder", "r_shoulder"}) {
    const int j = joint(name);
    const double medial = name[0] == 'l' ? -1.0 : 1.0;  // -X is medial for the left arm
    const Eigen::Quaterniond internal(
        Eigen::AngleAxisd(medial * deg(80), Eigen::Vector3d::UnitY()));
    const Eigen::Vector3d forearm = limits.clamp(j, internal) * Eigen::Vector3d::UnitZ();
    EXPECT_NEAR(forearm.x(), medial * std::sin(deg(70)), 1e-3) << name;
    const Eigen::Quaterniond external(
        Eigen::AngleAxisd(-medial * deg(80), Eigen::Vector3d::UnitY()));
    EXPECT_EQ(limits.excess(j, external), 0.0) << name;
  }
}

TEST_F(SikLimitsTest, ElbowsAndKneesAreHingesInTheirAnatomicalRange) {
  for (const char* name : {"l_elbow", "r_elbow", "l_knee", "r_knee"}) {
    const int j = joint(name);
    const SikJointLimit& l = limits[j];
    ASSERT_EQ(l.kind, SikLimitKind::hinge) << name;
    // A positive turn flexes: the forearm swings forward, the calf backward.
    const Eigen::Vector3d lower = Eigen::AngleAxisd(deg(90), l.pole) * body.segment_direction(j);
    EXPECT_GT(name[2] == 'e' ? lower.z() : -lower.z(), 0.9) << name;
    const double top = name[2] == 'e' ? deg(150) : deg(135);
    EXPECT_NEAR(l.max, top, 1e-12) << name;
    // Hyperextension clamps to straight, over-flexion to the top, and off-axis turns vanish.
    EXPECT_LT(limits.clamp(j, Eigen::Quaterniond(Eigen::AngleAxisd(-0.2, l.pole)))
                  .angularDistance(Eigen::Quaterniond::Identity()),
              1e-12);
    EXPECT_NEAR(
        Eigen::AngleAxisd(limits.clamp(j, Eigen::Quaterniond(Eigen::AngleAxisd(3.0, l.pole))))
            .angle(),
        top, 1e-9);
    const Eigen::Quaterniond twisted(Eigen::AngleAxisd(0.3, body.segment_direction(j)));
    EXPECT_NEAR(limits.excess(j, twisted), 0.3, 1e-9);
  }
}

TEST_F(SikLimitsTest, SpineRegionsShareTheirRangeAndTheRootIsFree) {
  EXPECT_EQ(limits[0].kind, SikLimitKind::free);
  // Six thoracolumbar joints share 80 degrees of flexion, two cervical ones 45.
  EXPECT_NEAR(limits.max_swing(joint("vl3"), 0.0), deg(80) / 6, 1e-12);
  EXPECT_NEAR(limits.max_swing(joint("vt6"), kPi), deg(25) / 6, 1e-12);
  EXPECT_NEAR(limits.max_swing(joint("vc4"), 0.0), deg(45) / 2, 1e-12);
  EXPECT_NEAR(limits[joint("vc7")].max, deg(60) / 2, 1e-12);
}

}  // namespace
}  // namespace simcap
