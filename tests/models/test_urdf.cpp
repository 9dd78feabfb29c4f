// URDF export: check_urdf accepts it, urdfdom reads back every limit and the same kinematics, and
// bad files are refused with the file and joint named.
#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <random>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"
#include "models/pose.h"
#include "models/urdf_io.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::error_of;
using testing::TempDir;

TEST(Urdf, CheckUrdfAcceptsTheFile) {
  TempDir dir;
  const auto path = dir / "body.urdf";
  write_humanoid_urdf(path, build_humanoid(), humanoid_joint_limits());
  const std::string command =
      "check_urdf '" + path.string() + "' > '" + (dir / "check.txt").string() + "' 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << read_text(dir / "check.txt");
  EXPECT_NE(read_text(dir / "check.txt").find("root Link: sacrum"), std::string::npos);
}

TEST(Urdf, UrdfdomReadsBackEveryLimitExactly) {
  const Skeleton s = build_humanoid();
  const auto model = urdf::parseURDF(humanoid_urdf(s, humanoid_joint_limits()));
  ASSERT_TRUE(model);
  EXPECT_EQ(model->getRoot()->name, "sacrum");
  size_t revolute = 0;
  for (const JointLimits& l : humanoid_joint_limits()) {
    for (const DofLimit& d : l.dofs) {
      const auto joint = model->getJoint(d.name);
      ASSERT_TRUE(joint) << d.name;
      EXPECT_EQ(joint->type, urdf::Joint::REVOLUTE);
      ASSERT_TRUE(joint->limits);
      EXPECT_EQ(joint->limits->lower, d.lower) << d.name;
      EXPECT_EQ(joint->limits->upper, d.upper) << d.name;
      EXPECT_EQ(Eigen::Vector3d(joint->axis.x, joint->axis.y, joint->axis.z), d.axis);
      ++revolute;
    }
  }
  size_t total_revolute = 0;
  for (const auto& [name, joint] : model->joints_)
    total_revolute += joint->type == urdf::Joint::REVOLUTE;
  EXPECT_EQ(total_revolute, revolute);
  for (const char* site : {"skull_tip", "l_hand_tip", "r_toe_tip"}) {
    ASSERT_TRUE(model->getJoint(site));
    EXPECT_EQ(model->getJoint(site)->type, urdf::Joint::FIXED);
  }
}

// Forward kinematics of the parsed URDF (origins and axes as urdfdom read them) at the DOF
// angles of a pose, compared with simcap's forward kinematics of that pose.
TEST(Urdf, ParsedKinematicsMatchSimcapForwardKinematics) {
  const Skeleton s = build_humanoid({.height = 1.68, .proportions = {}});
  const auto& table = humanoid_joint_limits();
  const auto model = urdf::parseURDF(humanoid_urdf(s, table));
  ASSERT_TRUE(model);

  std::mt19937 rng(9);
  Pose pose = Pose::neutral(s);
  std::map<std::string, double> angle_of;
  for (const JointLimits& l : table) {
    std::vector<double> angles;
    for (const DofLimit& d : l.dofs) {
      angles.push_back(std::uniform_real_distribution<double>(std::max(d.lower, -1.2),
                                                              std::min(d.upper, 1.2))(rng));
      angle_of[d.name] = angles.back();
    }
    pose.rotations[s.require(l.joint)] = dof_rotation(l, angles);
  }
  const auto expected = joint_positions(s, pose);

  std::map<std::string, Eigen::Isometry3d> link_world;
  std::function<void(const urdf::LinkConstSharedPtr&, const Eigen::Isometry3d&)> walk =
      [&](const auto& link, const Eigen::Isometry3d& world) {
        link_world[link->name] = world;
        for (const auto& joint : link->child_joints) {
          const auto& p = joint->parent_to_joint_origin_transform.position;
          Eigen::Isometry3d child = world * Eigen::Translation3d(p.x, p.y, p.z);
          if (joint->type == urdf::Joint::REVOLUTE) {
            child.rotate(
                Eigen::AngleAxisd(angle_of.at(joint->name),
                                  Eigen::Vector3d(joint->axis.x, joint->axis.y, joint->axis.z)));
          }
          walk(model->getLink(joint->child_link_name), child);
        }
      };
  walk(model->getRoot(), Eigen::Isometry3d(Eigen::Translation3d(s[0].center)));
  for (int j = 0; j < s.size(); ++j) {
    const std::string link = s[j].is_site ? s[j].name : s[j].segment;
    ASSERT_TRUE(link_world.count(link)) << link;
    EXPECT_LT((link_world[link].translation() - expected[j]).norm(), 1e-12) << s[j].name;
  }
}

TEST(Urdf, ReadLimitsRoundTrips) {
  TempDir dir;
  const Skeleton s = build_humanoid();
  const auto path = dir / "body.urdf";
  write_humanoid_urdf(path, s, humanoid_joint_limits());
  const std::vector<JointLimits> back = read_urdf_limits(path, s);
  const auto& table = humanoid_joint_limits();
  ASSERT_EQ(back.size(), table.size());
  for (const JointLimits& l : table) {
    const JointLimits* r = find_joint_limits(back, l.joint);
    ASSERT_TRUE(r) << l.joint;
    ASSERT_EQ(r->dofs.size(), l.dofs.size()) << l.joint;
    for (size_t d = 0; d < l.dofs.size(); ++d) {
      EXPECT_EQ(r->dofs[d].name, l.dofs[d].name);  // chain order preserved
      EXPECT_EQ(r->dofs[d].axis, l.dofs[d].axis);
      EXPECT_EQ(r->dofs[d].lower, l.dofs[d].lower);
      EXPECT_EQ(r->dofs[d].upper, l.dofs[d].upper);
      EXPECT_EQ(r->dofs[d].source, l.dofs[d].source);  // from the comment before the joint
    }
  }
  // Without the comments, a DOF's source is the file.
  std::string bare = read_text(path);
  for (size_t at; (at = bare.find("<!--")) != std::string::npos;) {
    bare.erase(at, bare.find("-->", at) + 3 - at);
  }
  write_text_atomic(path, bare);
  for (const JointLimits& l : read_urdf_limits(path, s)) {
    for (const DofLimit& d : l.dofs) EXPECT_EQ(d.source, "URDF " + path.string());
  }
}

TEST(Urdf, ShippedLimitsAreMoschinisTableWhereTheyCiteIt) {
  int cited = 0;
  for (const JointLimits& l : humanoid_joint_limits()) {
    for (const DofLimit& d : l.dofs) {
      if (!d.source.starts_with("Moschini 2009 Table 5.1")) continue;
      const JointLimits* m = find_joint_limits(moschini_joint_limits(), l.joint);
      ASSERT_TRUE(m) << d.name;
      const auto it = std::find_if(m->dofs.begin(), m->dofs.end(),
                                   [&](const DofLimit& x) { return x.name == d.name; });
      ASSERT_NE(it, m->dofs.end()) << d.name;
      EXPECT_EQ(d.lower, it->lower) << d.name;
      EXPECT_EQ(d.upper, it->upper) << d.name;
      EXPECT_EQ(d.source, it->source) << d.name;
      ++cited;
    }
  }
  EXPECT_EQ(cited, 16);  // his 16 angles
}

class BadUrdf : public ::testing::Test {
 protected:
  // The written URDF with `from` replaced by `to` once.
  std::filesystem::path edited(const std::string& from, const std::string& to) {
    std::string text = humanoid_urdf(skeleton_, humanoid_joint_limits());
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    const auto path = dir_ / "bad.urdf";
    write_text_atomic(path, text);
    return path;
  }
  TempDir dir_;
  Skeleton skeleton_ = build_humanoid();
};

TEST_F(BadUrdf, MissingLimitNamesFileAndJoint) {
  const std::string l_knee = "name=\"l_knee_flexion\" type=\"revolute\"";
  std::string text = humanoid_urdf(skeleton_, humanoid_joint_limits());
  const size_t joint = text.find(l_knee);
  ASSERT_NE(joint, std::string::npos);
  const size_t limit = text.find("<limit", joint);
  text.erase(limit, text.find("/>", limit) + 2 - limit);
  const auto path = dir_ / "no_limit.urdf";
  write_text_atomic(path, text);
  const std::string e = error_of([&] { read_urdf_limits(path, skeleton_); });
  EXPECT_NE(e.find("no_limit.urdf"), std::string::npos) << e;
  EXPECT_NE(e.find("l_knee_flexion"), std::string::npos) << e;
}

TEST_F(BadUrdf, UnknownJointNamesFileAndJoint) {
  const auto path = edited("\"l_elbow_flexion\"", "\"l_wing_flap\"");
  const std::string e = error_of([&] { read_urdf_limits(path, skeleton_); });
  EXPECT_NE(e.find("bad.urdf"), std::string::npos) << e;
  EXPECT_NE(e.find("l_wing_flap"), std::string::npos) << e;
}

TEST_F(BadUrdf, OtherProblemsAreErrors) {
  const std::string continuous = error_of([&] {
    read_urdf_limits(edited("name=\"r_knee_flexion\" type=\"revolute\"",
                            "name=\"r_knee_flexion\" type=\"continuous\""),
                     skeleton_);
  });
  EXPECT_NE(continuous.find("r_knee_flexion"), std::string::npos) << continuous;
  const std::string axis = error_of([&] {
    read_urdf_limits(edited("<axis xyz=\"1 0 0\"", "<axis xyz=\"0.6 0.8 0\""), skeleton_);
  });
  EXPECT_NE(axis.find("axis"), std::string::npos) << axis;
  EXPECT_NE(error_of([&] {
              read_urdf_limits(edited("<robot", "<robbery"), skeleton_);
            }).find("not a valid URDF"),
            std::string::npos);
  EXPECT_NE(
      error_of([&] { read_urdf_limits(dir_ / "missing.urdf", skeleton_); }).find("missing.urdf"),
      std::string::npos);
  std::vector<JointLimits> wrong = {{"l_wing", {}}};
  EXPECT_THROW(humanoid_urdf(skeleton_, wrong), Error);
}

}  // namespace
}  // namespace simcap
