// COCO-17 and Human3.6M-17 keypoints on simcap's humanoid and on JoeSkin.x3d: limb points are
// the H-Anim joints, face points sit on the head where a face has them, and every point moves
// rigidly with its joint.
#include <gtest/gtest.h>

#include <map>
#include <numbers>

#include "models/body_source.h"
#include "models/keypoint_sets.h"
#include "models/pose.h"
#include "models/x3d_humanoid.h"

namespace simcap {
namespace {

std::map<std::string, Eigen::Vector3d> neutral_points(const std::vector<BodyPoint>& points,
                                                      const Skeleton& s) {
  const auto world = forward_kinematics(s, Pose::neutral(s));
  std::map<std::string, Eigen::Vector3d> out;
  for (const BodyPoint& p : points) out[p.name] = body_point_world(p, world);
  return out;
}

void expect_face_on_the_head(const Body& body) {
  const Skeleton& s = body.skeleton;
  const auto p = neutral_points(coco17_points(s, body.mesh), s);
  ASSERT_EQ(p.size(), 17u);
  const Eigen::Vector3d skull = s[s.require("skullbase")].center;
  const Eigen::Vector3d top = s[s.require("skull_tip")].center;
  // The nose in front of the skull base, between it and the head top.
  EXPECT_GT(p.at("nose").z(), skull.z() + 0.05);
  EXPECT_GT(p.at("nose").y(), skull.y());
  EXPECT_LT(p.at("nose").y(), top.y());
  // Eyes above and behind the nose tip, left on +X; ears wider than the eyes, behind them.
  for (const char* side : {"left", "right"}) {
    const std::string s_(side);
    const double sign = s_ == "left" ? 1 : -1;
    EXPECT_GT(p.at(s_ + "_eye").y(), p.at("nose").y() - 0.01) << side;
    EXPECT_LT(p.at(s_ + "_eye").z(), p.at("nose").z()) << side;
    EXPECT_GT(sign * (p.at(s_ + "_eye").x() - p.at("nose").x()), 0.02) << side;
    EXPECT_GT(sign * p.at(s_ + "_ear").x(), sign * p.at(s_ + "_eye").x()) << side;
    EXPECT_LT(p.at(s_ + "_ear").z(), p.at(s_ + "_eye").z()) << side;
  }
  EXPECT_LT((p.at("left_wrist") - s[s.require("l_radiocarpal")].center).norm(), 1e-12);
  EXPECT_LT((p.at("right_ankle") - s[s.require("r_talocrural")].center).norm(), 1e-12);
}

TEST(KeypointSets, FacePointsLieOnTheHumanoidsHead) {
  expect_face_on_the_head(build_body({}));
}

TEST(KeypointSets, FacePointsLieOnJoesHeadWithHisEyeballJoints) {
  const Body joe = read_x3d_humanoid(SIMCAP_SOURCE_DIR "/models/assets/JoeSkin.x3d");
  expect_face_on_the_head(joe);
  const auto p = neutral_points(coco17_points(joe.skeleton, joe.mesh), joe.skeleton);
  EXPECT_LT(
      (p.at("left_eye") - joe.skeleton[joe.skeleton.require("l_eyeball_joint")].center).norm(),
      1e-12);
}

TEST(KeypointSets, Human36mOrderAndJoints) {
  for (const Body& body :
       {build_body({}), read_x3d_humanoid(SIMCAP_SOURCE_DIR "/models/assets/JoeSkin.x3d")}) {
    const Skeleton& s = body.skeleton;
    const auto points = h36m17_points(s, body.mesh);
    const std::vector<std::string> order = {"Hip",    "RHip",      "RKnee",  "RFoot",  "LHip",
                                            "LKnee",  "LFoot",     "Spine",  "Thorax", "Neck/Nose",
                                            "Head",   "LShoulder", "LElbow", "LWrist", "RShoulder",
                                            "RElbow", "RWrist"};
    ASSERT_EQ(points.size(), order.size());
    for (size_t k = 0; k < order.size(); ++k) EXPECT_EQ(points[k].name, order[k]);
    EXPECT_EQ(s[points[7].joint].name, "vt10");
    EXPECT_EQ(s[points[10].joint].name, "skull_tip");
    const auto p = neutral_points(points, s);
    EXPECT_LT(
        (p.at("Hip") - 0.5 * (s[s.require("l_hip")].center + s[s.require("r_hip")].center)).norm(),
        1e-12);
  }
}

TEST(KeypointSets, PointsMoveRigidlyWithTheirJoint) {
  const Body body = build_body({});
  const Skeleton& s = body.skeleton;
  const auto points = coco17_points(s, body.mesh);
  Pose pose = Pose::neutral(s);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()));
  pose.rotations[s.require("skullbase")] = turn;
  const auto world = forward_kinematics(s, pose);
  const auto neutral = neutral_points(points, s);
  const Eigen::Vector3d c = s[s.require("skullbase")].center;
  // Turning the head a quarter left brings the nose round to +X.
  const Eigen::Vector3d nose = body_point_world(points[0], world);
  EXPECT_LT((nose - (c + turn * (neutral.at("nose") - c))).norm(), 1e-12);
  EXPECT_GT(nose.x(), c.x() + 0.05);
}

}  // namespace
}  // namespace simcap
