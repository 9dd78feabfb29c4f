// Joint limits: coverage of the humanoid, sign conventions, the mapping of Moschini's Table 5.1
// checked against his own kinematics (eqs. 5.26-5.41, Tables 5.2-5.3), and the DOF Euler angles.
#include <gtest/gtest.h>

#include <numbers>
#include <random>
#include <set>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;
const Eigen::Vector3d kX = Eigen::Vector3d::UnitX(), kY = Eigen::Vector3d::UnitY(),
                      kZ = Eigen::Vector3d::UnitZ();

const JointLimits& limits_of(const std::vector<JointLimits>& table, const std::string& joint) {
  const JointLimits* l = find_joint_limits(table, joint);
  if (!l) throw Error("no limits for " + joint);
  return *l;
}

Eigen::Vector3d turn(const std::string& joint, const std::vector<double>& angles,
                     const Eigen::Vector3d& v) {
  return dof_rotation(limits_of(humanoid_joint_limits(), joint), angles) * v;
}

TEST(JointLimits, CoverEveryMovableJointOfTheHumanoid) {
  const Skeleton s = build_humanoid();
  const auto& table = humanoid_joint_limits();
  std::set<std::string> covered, dof_names;
  for (const JointLimits& l : table) {
    EXPECT_TRUE(covered.insert(l.joint).second) << l.joint;
    const int j = s.find(l.joint);
    ASSERT_GT(j, 0) << l.joint;
    EXPECT_FALSE(s[j].is_site);
    ASSERT_FALSE(l.dofs.empty());
    // Axes are a subsequence of Z, X, Y.
    const std::vector<Eigen::Vector3d> order = {kZ, kX, kY};
    size_t next = 0;
    for (const DofLimit& d : l.dofs) {
      EXPECT_TRUE(dof_names.insert(d.name).second) << d.name;
      EXPECT_EQ(d.name.rfind(l.joint + "_", 0), 0u) << d.name;
      while (next < order.size() && order[next] != d.axis) ++next;
      EXPECT_LT(next++, order.size()) << d.name << " breaks the Z, X, Y order";
      EXPECT_LE(d.lower, 0.0) << d.name << ": the neutral pose must be allowed";
      EXPECT_GE(d.upper, 0.0) << d.name;
      EXPECT_LT(d.lower, d.upper) << d.name;
      EXPECT_LE(d.upper - d.lower, 2 * kPi + 1e-12) << d.name;
      EXPECT_FALSE(d.source.empty()) << d.name;
    }
  }
  for (int j = 1; j < s.size(); ++j) {
    if (!s[j].is_site) {
      EXPECT_TRUE(covered.count(s[j].name)) << s[j].name;
    }
  }
  for (const char* hinge : {"l_elbow", "r_knee", "l_metatarsophalangeal_2"}) {
    ASSERT_EQ(limits_of(table, hinge).dofs.size(), 1u);
    EXPECT_EQ(limits_of(table, hinge).dofs[0].axis, kX);
  }
  for (const char* ball : {"l_shoulder", "r_hip", "vt6", "skullbase", "l_radiocarpal"}) {
    EXPECT_EQ(limits_of(table, ball).dofs.size(), 3u) << ball;
  }
}

TEST(JointLimits, SignsMatchTheAnatomy) {
  const auto& t = humanoid_joint_limits();
  const Eigen::Vector3d down = -kY, up = kY, forward = kZ;
  // Elbow flexion (negative about +X) brings the forearm forward on both sides.
  for (const char* elbow : {"l_elbow", "r_elbow"}) {
    const DofLimit& d = limits_of(t, elbow).dofs[0];
    EXPECT_GT(turn(elbow, {d.lower / 2}, down).dot(forward), 0.9) << elbow;
    EXPECT_EQ(d.upper, 0.0);
  }
  // Knee flexion (positive) swings the calf backward.
  EXPECT_LT(turn("l_knee", {kPi / 2}, down).dot(forward), -0.9);
  // Left arm abduction is positive about +Z, the right arm's negative.
  EXPECT_GT(turn("l_shoulder", {kPi / 2, 0, 0}, down).dot(kX), 0.9);
  EXPECT_LT(turn("r_shoulder", {-kPi / 2, 0, 0}, down).dot(kX), -0.9);
  EXPECT_GT(limits_of(t, "l_shoulder").dofs[0].upper, kPi / 2);
  EXPECT_LT(limits_of(t, "r_shoulder").dofs[0].lower, -kPi / 2);
  // Hip flexion is negative (thigh forward) and allowed further than extension.
  const DofLimit& hip = limits_of(t, "l_hip").dofs[1];
  EXPECT_GT(turn("l_hip", {0, -1.0, 0}, down).dot(forward), 0.8);
  EXPECT_GT(-hip.lower, hip.upper);
  // Trunk flexion is positive (the upper body tips forward), ankle plantar flexion positive.
  EXPECT_GT(turn("vl3", {0, 0.2, 0}, up).dot(forward), 0.19);
  EXPECT_GT(limits_of(t, "vl3").dofs[1].upper, -limits_of(t, "vl3").dofs[1].lower);
  EXPECT_LT(turn("l_talocrural", {0, 0.5}, forward).dot(up), -0.4);
  EXPECT_GT(limits_of(t, "l_talocrural").dofs[1].upper,
            -limits_of(t, "l_talocrural").dofs[1].lower);
  // Left clavicle elevation is positive about +Z.
  EXPECT_GT(turn("l_sternoclavicular", {0.5, 0}, kX).dot(up), 0.4);
  EXPECT_GT(limits_of(t, "l_sternoclavicular").dofs[0].upper, 0.7);
  // Wrist flexion turns the hanging hand's fingers towards the thigh (the palm's side), further
  // than extension; radial deviation (negative) towards the thumb in front.
  for (const auto& [wrist, medial] : {std::pair{"l_radiocarpal", -1.0}, {"r_radiocarpal", 1.0}}) {
    const DofLimit& flexion = limits_of(t, wrist).dofs[0];
    const double flexed = medial < 0 ? flexion.lower : flexion.upper;
    EXPECT_GT(turn(wrist, {flexed, 0, 0}, down).dot(medial * kX), 0.9) << wrist;
    EXPECT_GT(std::abs(flexed), medial < 0 ? flexion.upper : -flexion.lower) << wrist;
    EXPECT_GT(turn(wrist, {0, -0.3, 0}, down).dot(forward), 0.25) << wrist;
  }
}

// Moschini's rotation matrices (eqs. 5.26-5.41) in his own axes: X forward, Y left, Z up.
Eigen::Matrix3d moschini_rotation(char axis, double angle) {
  const Eigen::Vector3d a = axis == 'x' ? kX : axis == 'y' ? kY : kZ;
  return Eigen::AngleAxisd(angle, a).toRotationMatrix();
}

// His vector (x, y, z) is simcap's (y, z, x).
Eigen::Matrix3d moschini_to_simcap() {
  Eigen::Matrix3d p;
  p << 0, 1, 0, 0, 0, 1, 1, 0, 0;
  return p;
}

double uniform(std::mt19937& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// The simcap angles of a thesis angle, as the table says.
double mapped(const DofLimit& d, double thesis_angle) {
  return d.source_sign * thesis_angle + d.source_offset;
}

TEST(JointLimits, MoschiniMappingReproducesHisArmKinematics) {
  const auto& table = moschini_joint_limits();
  const Eigen::Matrix3d P = moschini_to_simcap();
  // simcap's neutral arm hangs down; his zero arm points along his +Y (Table 5.3, t8.4, t9.5).
  const Eigen::Matrix3d raise = Eigen::AngleAxisd(kPi / 2, kZ).toRotationMatrix();
  std::mt19937 rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    for (const char* side : {"l_", "r_"}) {
      const bool left = side[0] == 'l';
      const JointLimits& sh = limits_of(table, std::string(side) + "shoulder");
      const JointLimits& el = limits_of(table, std::string(side) + "elbow");
      // Thesis angles drawn from Table 5.1's ranges.
      const double t1 = left ? uniform(rng, -kPi, kPi) : uniform(rng, 0, 2 * kPi);
      const double t2 = uniform(rng, -kPi, kPi / 2);
      const double t3 =
          left ? uniform(rng, -kPi / 2, 3 * kPi / 4) : uniform(rng, -3 * kPi / 4, kPi / 2);
      const double t4 = uniform(rng, -kPi, 0);
      // Table 5.2: the elbow is placed by R3 R5, the hand by R3 R5 R7 R9 (R4 R6 R8 R10 on the
      // right); R7 spins the upper arm about its own axis.
      const Eigen::Matrix3d thesis_placement =
          moschini_rotation('x', t1) * moschini_rotation('z', t2);
      const Eigen::Matrix3d thesis_upper = thesis_placement * moschini_rotation('y', t3);
      const Eigen::Matrix3d thesis_fore = thesis_upper * moschini_rotation('z', t4);
      const std::vector<double> sh_angles = {mapped(sh.dofs[0], t1), mapped(sh.dofs[1], t2),
                                             mapped(sh.dofs[2], t3)};
      const Eigen::Matrix3d upper = dof_rotation(sh, sh_angles).toRotationMatrix();
      const Eigen::Matrix3d fore =
          upper * dof_rotation(el, std::vector<double>{mapped(el.dofs[0], t4)}).toRotationMatrix();
      // Whole frames agree, so directions, elbow bend and spin all agree.
      EXPECT_LT((upper - P * thesis_upper * P.transpose() * raise).norm(), 1e-9);
      // The upper arm (t8.4 = [0, 2 lambda, 0]) points the same way.
      EXPECT_LT((upper * -kY - P * thesis_placement * kY).norm(), 1e-9);
      EXPECT_LT((fore - P * thesis_fore * P.transpose() * raise).norm(), 1e-9);
      // Every mapped angle lies within the mapped limits.
      for (size_t d = 0; d < 3; ++d) {
        EXPECT_GE(sh_angles[d], sh.dofs[d].lower - 1e-12);
        EXPECT_LE(sh_angles[d], sh.dofs[d].upper + 1e-12);
      }
    }
  }
}

TEST(JointLimits, MoschiniMappingReproducesHisLegAndNeckKinematics) {
  const auto& table = moschini_joint_limits();
  const Eigen::Matrix3d P = moschini_to_simcap();
  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    const double hip1 = uniform(rng, -kPi / 3, kPi / 2), hip2 = uniform(rng, -kPi, kPi / 2),
                 knee = uniform(rng, 0, kPi);
    const JointLimits& hip = limits_of(table, "l_hip");
    const JointLimits& kn = limits_of(table, "l_knee");
    const Eigen::Matrix3d thesis =
        moschini_rotation('x', hip1) * moschini_rotation('y', hip2) * moschini_rotation('y', knee);
    const Eigen::Matrix3d ours =
        (dof_rotation(hip,
                      std::vector<double>{mapped(hip.dofs[0], hip1), mapped(hip.dofs[1], hip2)}) *
         dof_rotation(kn, std::vector<double>{mapped(kn.dofs[0], knee)}))
            .toRotationMatrix();
    EXPECT_LT((ours - P * thesis * P.transpose()).norm(), 1e-9);

    const double n1 = uniform(rng, -kPi / 2, kPi / 2), n2 = uniform(rng, -kPi / 2, kPi / 2);
    const JointLimits& neck = limits_of(table, "vc7");
    const Eigen::Matrix3d thesis_neck = moschini_rotation('x', n1) * moschini_rotation('y', n2);
    const Eigen::Matrix3d our_neck =
        dof_rotation(neck, std::vector<double>{mapped(neck.dofs[0], n1), mapped(neck.dofs[1], n2)})
            .toRotationMatrix();
    EXPECT_LT((our_neck - P * thesis_neck * P.transpose()).norm(), 1e-9);
  }
  // Sixteen angles in all, as in the thesis.
  size_t count = 0;
  for (const JointLimits& l : table) count += l.dofs.size();
  EXPECT_EQ(count, 16u);
}

TEST(JointLimits, GomezTableHasItsTwentyAngles) {
  size_t count = 0;
  for (const JointLimits& l : gomez_joint_limits()) count += l.dofs.size();
  EXPECT_EQ(count, 20u);
  const DofLimit& flexion = limits_of(gomez_joint_limits(), "l_shoulder").dofs[1];
  EXPECT_EQ(flexion.name, "l_shoulder_flexion");
  EXPECT_NEAR(flexion.lower, -110 * kPi / 180, 1e-12);
  EXPECT_NEAR(flexion.upper, 25 * kPi / 180, 1e-12);
  // The humanoid's own table keeps anatomical wrists: real motion bends them beyond it.
  EXPECT_LT(limits_of(gomez_joint_limits(), "r_radiocarpal").dofs[0].upper,
            limits_of(humanoid_joint_limits(), "r_radiocarpal").dofs[0].upper);
}

TEST(JointLimits, DofAnglesInvertDofRotation) {
  std::mt19937 rng(3);
  for (const JointLimits& l : humanoid_joint_limits()) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> angles;
      for (const DofLimit& d : l.dofs) {
        const double hi = d.axis == kX ? std::min(d.upper, 1.5) : d.upper;
        const double lo = d.axis == kX ? std::max(d.lower, -1.5) : d.lower;
        angles.push_back(uniform(rng, std::max(lo, -3.1), std::min(hi, 3.1)));
      }
      const std::vector<double> back = dof_angles(l, dof_rotation(l, angles));
      ASSERT_EQ(back.size(), angles.size());
      for (size_t i = 0; i < angles.size(); ++i) EXPECT_NEAR(back[i], angles[i], 1e-9) << l.joint;
    }
  }
  EXPECT_THROW(
      dof_rotation(limits_of(humanoid_joint_limits(), "l_elbow"), std::vector<double>{1, 2}),
      Error);
}

TEST(JointLimits, LimitExcessIsZeroInsideAndTheOvershootOutside) {
  std::mt19937 rng(5);
  for (const JointLimits& l : humanoid_joint_limits()) {
    for (int trial = 0; trial < 20; ++trial) {
      std::vector<double> angles;
      for (const DofLimit& d : l.dofs) angles.push_back(uniform(rng, d.lower, d.upper));
      EXPECT_LT(limit_excess(l, dof_rotation(l, angles)), 1e-9) << l.joint;
    }
  }
  const auto rot = [](const Eigen::Vector3d& axis, double a) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(a, axis));
  };
  const JointLimits& knee = limits_of(humanoid_joint_limits(), "l_knee");
  const JointLimits& hip = limits_of(humanoid_joint_limits(), "l_hip");
  EXPECT_NEAR(limit_excess(knee, rot(kX, -0.2)), 0.2, 1e-9);                // hyperextended
  EXPECT_NEAR(limit_excess(knee, rot(kX, 1.0) * rot(kY, 0.1)), 0.1, 1e-9);  // a knee cannot twist
  EXPECT_LT(limit_excess(hip, rot(kX, -2.4)), 1e-9);                        // deep flexion
  EXPECT_NEAR(limit_excess(hip, rot(kX, 1.8)), 1.8 - kPi / 2, 1e-9);        // far behind
}

TEST(JointLimits, LimitExcessMatchesABruteForceSearch) {
  // Near gimbal lock (hip flexed 90 degrees) a rotation's Euler angles can lie far outside the
  // box while one within it is close: compare with the best of a grid over the box.
  std::mt19937 rng(11);
  const auto rot = [](const Eigen::Vector3d& axis, double a) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(a, axis));
  };
  for (const char* name : {"r_hip", "l_shoulder"}) {
    const JointLimits& l = limits_of(humanoid_joint_limits(), name);
    for (int trial = 0; trial < 4; ++trial) {
      const Eigen::Quaterniond q = rot(kZ, uniform(rng, -kPi, kPi)) *
                                   rot(kX, uniform(rng, -1.75, -1.4)) *
                                   rot(kY, uniform(rng, -kPi, kPi));
      double best = INFINITY;
      const double step = 2 * kPi / 180;
      for (double a = l.dofs[0].lower; a <= l.dofs[0].upper; a += step) {
        for (double b = l.dofs[1].lower; b <= l.dofs[1].upper; b += step) {
          for (double c = l.dofs[2].lower; c <= l.dofs[2].upper; c += step) {
            const Eigen::AngleAxisd e(q.conjugate() * rot(kZ, a) * rot(kX, b) * rot(kY, c));
            best = std::min(best, e.angle());
          }
        }
      }
      const double excess = limit_excess(l, q);
      EXPECT_LE(excess, best + 1e-9) << name;
      EXPECT_GT(excess, best - 2 * step) << name;  // the grid is 2 degrees coarse
    }
  }
}

TEST(JointLimits, MarkdownListsEveryDof) {
  const std::string md = joint_limits_markdown(humanoid_joint_limits());
  for (const JointLimits& l : humanoid_joint_limits()) {
    for (const DofLimit& d : l.dofs) EXPECT_NE(md.find("| " + d.name + " |"), std::string::npos);
  }
  EXPECT_NE(md.find("| l_elbow | l_elbow_flexion | +X | -180.0 | 0.0 |"), std::string::npos);
}

}  // namespace
}  // namespace simcap
