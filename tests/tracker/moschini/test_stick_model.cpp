#include <gtest/gtest.h>

#include <random>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/pose.h"
#include "tracker/moschini/pose_init.h"
#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {
namespace {

Angles random_angles(const StickModel& model, std::mt19937& rng) {
  Angles theta{};
  const auto& ranges = model.ranges();
  for (int k = 0; k < model.angle_count(); ++k) {
    // Stay clear of the Euler singularity (flexion ±90°) where the split is not unique.
    const double lo = std::max(ranges[k].lo, -1.3), hi = std::min(ranges[k].hi, 1.3);
    theta[k] = std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return theta;
}

TEST(StickModel, SegmentRotationRoundTripsThroughTheAngles) {
  std::mt19937 rng(1);
  for (JointSet set : {JointSet::moschini, JointSet::urdf}) {
    const StickModel model(BodyDimensions{}, set);
    for (int trial = 0; trial < 50; ++trial) {
      StickPose pose;
      pose.theta = random_angles(model, rng);
      const StickGeometry g = model.geometry(pose);
      StickPose copy = pose;
      copy.theta.fill(0.0);
      for (int s = 1; s < kSegmentCount; ++s) model.set_segment_rotation(copy, s, g.rotation[s]);
      const StickGeometry h = model.geometry(copy);
      for (int s = 0; s < kSegmentCount; ++s) {
        // The stick ends agree; a leaf's own spin about its axis is not a model parameter.
        EXPECT_LT((h.distal[s] - g.distal[s]).norm(), 1e-9) << segment_name(s);
      }
    }
  }
}

TEST(StickModel, JointsStayConnectedAndSticksKeepTheirLengths) {
  std::mt19937 rng(2);
  const StickModel model(BodyDimensions{}, JointSet::urdf);
  StickPose pose;
  pose.t0 = {0.2, 1.1, -0.4};
  pose.R0 = Eigen::AngleAxisd(0.8, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix();
  pose.theta = random_angles(model, rng);
  const StickGeometry g = model.geometry(pose);
  for (int s = 0; s < kSegmentCount; ++s) {
    EXPECT_NEAR((g.distal[s] - g.proximal[s]).norm(), model.length(s), 1e-12);
    const int p = segment_parent(s);
    if (!is_trunk(p) && p >= 0) {
      EXPECT_LT((g.proximal[s] - g.distal[p]).norm(), 1e-12);
    }
  }
  EXPECT_LT((g.proximal[kHead] - g.distal[kChest]).norm(), 1e-12);
  EXPECT_LT((g.proximal[kChest] - g.distal[kPelvis]).norm(), 1e-12);
}

TEST(StickModel, LimitsClampOrWrap) {
  const AngleRange knee{0.0, 3.14};
  EXPECT_DOUBLE_EQ(limit_angle(-0.2, knee), 0.0);
  EXPECT_DOUBLE_EQ(limit_angle(1.0, knee), 1.0);
  const AngleRange turn{-1.0, -1.0 + 2 * 3.141592653589793, true};
  EXPECT_NEAR(limit_angle(-1.5, turn), -1.5 + 2 * 3.141592653589793, 1e-12);
}

// The neutral humanoid's own joints give the stick model back with (almost) no error: lengths,
// offsets and the HE15 mapping are consistent with models/humanoid.h.
TEST(StickModel, ReproducesTheHumanoidsHe15JointsFromItsJoints) {
  const Skeleton s = build_humanoid();
  Pose p = Pose::neutral(s);
  p.rotations[s.require("l_elbow")] =
      Eigen::Quaterniond(Eigen::AngleAxisd(-1.0, Eigen::Vector3d::UnitX()));
  p.rotations[s.require("r_knee")] =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Eigen::Vector3d::UnitX()));
  p.rotations[s.require("l_hip")] =
      Eigen::Quaterniond(Eigen::AngleAxisd(-0.5, Eigen::Vector3d::UnitX()));
  const auto positions = joint_positions(s, p);
  NamedJoints joints;
  for (int i = 0; i < s.size(); ++i) joints[s[i].name] = positions[i];
  const StickModel model(dimensions_from_joints(joints, "test"), JointSet::urdf);
  const StickPose pose = pose_from_joints(model, joints, "test");
  const auto he15 = model.he15(pose);
  for (size_t i = 0; i < he15.size(); ++i) {
    EXPECT_LT((he15[i] - joints.at(he15_joints()[i])).norm(), 0.015) << he15_joints()[i];
  }
}

// The rotations the tracker writes to angles.csv are the humanoid's own where the sticks have
// its joints: the same pose, turned, read back through the sticks.
TEST(StickModel, JointRotationsAreTheHumanoidsLocalRotations) {
  const Skeleton s = build_humanoid();
  Pose p = Pose::neutral(s);
  const auto turn = [](double a, const Eigen::Vector3d& axis) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(a, axis.normalized()));
  };
  p.rotations[s.require("humanoid_root")] = turn(0.7, Eigen::Vector3d::UnitY());
  p.rotations[s.require("l_elbow")] = turn(-1.0, Eigen::Vector3d::UnitX());
  p.rotations[s.require("r_knee")] = turn(0.8, Eigen::Vector3d::UnitX());
  p.rotations[s.require("l_hip")] = turn(-0.5, Eigen::Vector3d(1, 0, 0.3));
  p.rotations[s.require("r_shoulder")] = turn(-0.6, Eigen::Vector3d(1, 0, -0.5));
  const auto positions = joint_positions(s, p);
  NamedJoints joints;
  for (int i = 0; i < s.size(); ++i) joints[s[i].name] = positions[i];
  const StickModel model(dimensions_from_joints(joints, "test"), JointSet::urdf);
  const std::vector<Eigen::Quaterniond> q =
      model.joint_rotations(pose_from_joints(model, joints, "test"));
  ASSERT_EQ(q.size(), rotation_joints().size());
  for (size_t k = 0; k < q.size(); ++k) {
    const std::string& name = rotation_joints()[k];
    const int j = s.require(name);
    const Eigen::Quaterniond truth = p.rotations[j];
    if (name == "humanoid_root") {
      EXPECT_LT(q[k].angularDistance(truth), 0.06) << name;
      continue;
    }
    // The sticks cannot see a limb's twist about its own axis: compare where each rotation
    // turns the bone below the joint.
    int child = -1;
    for (int i = 0; i < s.size() && child < 0; ++i) child = s[i].parent == j ? i : -1;
    const Eigen::Vector3d bone = (s[child].center - s[j].center).normalized();
    // A stick's ankle flexes about one axis and cannot turn the foot out by the 5-6 degrees the
    // humanoid's neutral foot is turned.
    const double tolerance = name.ends_with("talocrural") ? 0.12 : 0.05;
    EXPECT_LT(std::acos(std::clamp((q[k] * bone).dot(truth * bone), -1.0, 1.0)), tolerance) << name;
  }
}

// A body the sticks cannot hold (shoulders raised far above the trunk) is refused in terms of
// the body, naming where it came from.
TEST(StickModel, ABodyTheSticksCannotHoldIsNamedInWordsOfTheBody) {
  const Skeleton s = build_humanoid();
  const auto positions = joint_positions(s, Pose::neutral(s));
  NamedJoints joints;
  for (int i = 0; i < s.size(); ++i) joints[s[i].name] = positions[i];
  for (const char* side : {"l_shoulder", "r_shoulder"}) joints[side].y() += 0.6;
  try {
    dimensions_from_joints(joints, "gt/joints3d.csv");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(
        what.find("gt/joints3d.csv: the body there is one Moschini's stick model cannot hold"),
        std::string::npos)
        << what;
    EXPECT_NE(what.find("the shoulders' height above the trunk's centre"), std::string::npos)
        << what;
  }
}

}  // namespace
}  // namespace simcap::tracker
