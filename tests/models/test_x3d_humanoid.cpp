// The H-Anim X3D reader on the shipped JoeSkin.x3d: joints and skin as the file states them
// (checked against the file's own text), skinning about the file's joint centres, a CMU clip
// retargeted onto Joe, and malformed copies of the file reported as file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/foot_contact.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "models/x3d_humanoid.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::error_of;

const std::filesystem::path kJoe = SIMCAP_SOURCE_DIR "/models/assets/JoeSkin.x3d";

const std::string& joe_text() {
  static const std::string text = read_text(kJoe);
  return text;
}

int line_of(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// The file with its first `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = joe_text();
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string parse_error(const std::string& text) {
  return error_of([&] { parse_x3d_humanoid(text, "joe.x3d"); });
}

TEST(X3dHumanoid, ReadsJoesJointsAsTheFileStatesThem) {
  const Body joe = read_x3d_humanoid(kJoe);
  const Skeleton& s = joe.skeleton;
  // Every DEF'd HAnimJoint of the file, by an independent scan of its text.
  const std::string& text = joe_text();
  auto attribute = [](const std::string& tag, const std::string& name) {
    const size_t at = tag.find(" " + name + "=\"");
    if (at == std::string::npos) return std::string();
    const size_t start = at + name.size() + 3;
    return tag.substr(start, tag.find('"', start) - start);
  };
  int joints = 0;
  for (size_t at = 0; (at = text.find("<HAnimJoint DEF=", at)) != std::string::npos; ++at) {
    const std::string tag = text.substr(at, text.find('>', at) - at);
    ++joints;
    const int j = s.find(attribute(tag, "name"));
    ASSERT_GE(j, 0) << attribute(tag, "name");
    std::istringstream centre(attribute(tag, "center"));
    Eigen::Vector3d c;
    centre >> c.x() >> c.y() >> c.z();
    EXPECT_EQ(s[j].center, c) << s[j].name;
  }
  EXPECT_EQ(joints, 89);
  EXPECT_EQ(s[0].name, "humanoid_root");
  EXPECT_EQ(s[s.require("l_knee")].parent, s.require("l_hip"));
  EXPECT_EQ(s[s.require("l_knee")].segment, "l_calf");
  EXPECT_EQ(s[s.require("vt12")].segment, "t12");
  EXPECT_EQ(s[s.require("l_carpometacarpal_2")].segment, "l_metacarpal_2");
  // Added end sites (Joe's only site, RootFront, is not one of simcap's).
  int sites = 0;
  for (const Joint& j : s.joints()) sites += j.is_site;
  EXPECT_EQ(sites, 5);
  EXPECT_EQ(s.size(), 89 + 5);
  EXPECT_NEAR(s[s.require("skull_tip")].center.y(), 1.77, 1e-6);  // Joe's highest skin point
  EXPECT_GT(s[s.require("l_toe_tip")].center.z(),
            s[s.require("l_metatarsophalangeal_2")].center.z());
}

TEST(X3dHumanoid, ReadsJoesSkinAndWeights) {
  const Body joe = read_x3d_humanoid(kJoe);
  const BodyMesh& m = joe.mesh;
  EXPECT_EQ(m.triangles.size(), 695u);  // all triangles in the file
  EXPECT_EQ(m.vertices.size(), 349u);   // 390 points, 41 used by no triangle
  for (size_t v = 0; v < m.vertices.size(); ++v) {
    float sum = 0;
    for (float w : m.influence_weight[v]) sum += w;
    EXPECT_NEAR(sum, 1.0f, 1e-6f);
    EXPECT_EQ(m.vertex_segment[v], m.influence_joint[v][0]);
  }
  // The file's flaw is reported, with its line.
  const std::string elbow_line = std::to_string(line_of(joe_text(), "name=\"l_elbow\""));
  EXPECT_TRUE(std::any_of(joe.notes.begin(), joe.notes.end(), [&](const std::string& n) {
    return n.find("JoeSkin.x3d:" + elbow_line + ": HAnimJoint 'l_elbow' has 15") != n.npos;
  })) << ::testing::PrintToString(joe.notes);
  // Every material region but hair (which a skin without one cannot have) is used.
  for (MaterialRegion r : {MaterialRegion::skin, MaterialRegion::shirt, MaterialRegion::trousers,
                           MaterialRegion::shoes}) {
    EXPECT_NE(std::find(m.triangle_material.begin(), m.triangle_material.end(), r),
              m.triangle_material.end())
        << material_region_name(r);
  }
}

TEST(X3dHumanoid, SkinTurnsAboutTheFilesJointCentres) {
  const Body joe = read_x3d_humanoid(kJoe);
  const Skeleton& s = joe.skeleton;
  const int knee = s.require("l_knee");
  Pose pose = Pose::neutral(s);
  const Eigen::Quaterniond bend(Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitX()));
  pose.rotations[knee] = bend;
  std::vector<float> out(3 * joe.mesh.vertices.size() + 1);
  Skinner(s, joe.mesh).skin(forward_kinematics(s, pose), out.data());
  int below_knee = 0;
  for (size_t v = 0; v < joe.mesh.vertices.size(); ++v) {
    const Eigen::Vector3d p = joe.mesh.vertices[v].cast<double>();
    const Eigen::Vector3d q(out[3 * v], out[3 * v + 1], out[3 * v + 2]);
    double w_below = 0;  // weight of the knee and the joints below it
    for (int k = 0; k < 4; ++k) {
      if (s.is_descendant(joe.mesh.influence_joint[v][k], knee)) {
        w_below += joe.mesh.influence_weight[v][k];
      }
    }
    const Eigen::Vector3d c = s[knee].center;
    const Eigen::Vector3d expected = p + w_below * ((bend * (p - c) + c) - p);
    EXPECT_NEAR((q - expected).norm(), 0.0, 1e-5) << "vertex " << v;
    below_knee += w_below == 1.0;
  }
  EXPECT_GT(below_knee, 20);
}

TEST(X3dHumanoid, CmuClipRetargetsOntoJoe) {
  const Body joe = read_x3d_humanoid(kJoe);
  MotionSource source;
  source.bvh = SIMCAP_SOURCE_DIR "/models/assets/cmu_131_01_start_walk_stop.bvh";
  const Motion motion = load_motion(source, joe.skeleton, 30.0);
  ASSERT_GT(motion.frames.size(), 200u);
  // Joe's feet stand on the floor most of the time, and his bones keep their lengths.
  const FootTrack feet = humanoid_feet(joe.skeleton, motion);
  EXPECT_NEAR(median_lowest_point(feet), 0.0, 1e-6);
  const auto p = joint_positions(joe.skeleton, motion.frames[150]);
  for (int j = 1; j < joe.skeleton.size(); ++j) {
    EXPECT_NEAR((p[j] - p[joe.skeleton[j].parent]).norm(), joe.skeleton.offset(j).norm(), 1e-9);
  }
}

TEST(X3dHumanoid, TruncatedFileNamesTheLine) {
  const std::string& text = joe_text();
  const std::string cut = text.substr(0, text.size() / 2);
  const std::string e = parse_error(cut);
  EXPECT_NE(e.find("joe.x3d:"), e.npos) << e;
  EXPECT_NE(e.find("not well-formed XML"), e.npos) << e;
}

TEST(X3dHumanoid, FewerWeightsThanIndicesIsAnError) {
  const std::string text = edited(
      R"(skinCoordIndex="334 335 336 337 338 339 340 341" skinCoordWeight="1 1 1 1 1 1 1 1")",
      R"(skinCoordIndex="334 335 336 337 338 339 340 341" skinCoordWeight="1 1 1")");
  EXPECT_EQ(parse_error(text),
            "joe.x3d:" + std::to_string(line_of(text, "name=\"l_knee\"")) +
                ": HAnimJoint 'l_knee': skinCoordWeight: expected 8 weights (one per "
                "skinCoordIndex), got 3");
}

TEST(X3dHumanoid, UnknownJointNamesLeaveRequiredJointsMissing) {
  const std::string text = edited(R"(name="l_knee")", R"(name="LeftKnee")");
  EXPECT_EQ(parse_error(text), "joe.x3d: the humanoid lacks H-Anim joints simcap needs: l_knee");
}

TEST(X3dHumanoid, MalformedFieldsNameTheirLine) {
  struct Case {
    std::string from, to, line_of, message;
  };
  const Case cases[] = {
      {R"(center="0.115000002086163 0.465999990701675 0")", R"(center="0.115 abc 0")",
       "name=\"l_knee\"", "HAnimJoint 'l_knee': center: expected a number, got 'abc'"},
      {R"(center="0.115000002086163 0.465999990701675 0")", R"(center="0.115 0.466")",
       "name=\"l_knee\"", "HAnimJoint 'l_knee': center: expected 3 numbers, got 2"},
      {R"(skinCoordIndex="334 335)", R"(skinCoordIndex="3340 335)", "name=\"l_knee\"",
       "HAnimJoint 'l_knee': skinCoordIndex: expected indices in [0, 390), got 3340"},
      {R"(name="l_knee")", R"(name="l_hip")", "name=\"l_hip\" center=\"0.115",
       "HAnimJoint 'l_hip': the name is used by another joint"},
      {R"(name="l_knee")", R"(name="l_knee" rotation="1 0 0 0.5")", "name=\"l_knee\"",
       "HAnimJoint HAnimJoint 'l_knee': rotation: simcap reads humanoids in their default pose; "
       "expected 0 0 1 0, got '1 0 0 0.5'"},
      {R"(USE="hanim_l_hip")", R"(USE="nobody")", "USE=\"nobody\"",
       "HAnimJoint USE='nobody': expected the DEF name of a node, found none"},
      {R"(coordIndex="0 9 5 -1)", R"(coordIndex="0 9 -1)", "<IndexedFaceSet",
       "IndexedFaceSet coordIndex: expected polygons of 3 or more corners, got 2"},
      {R"(coordIndex="0 9 5 -1)", R"(coordIndex="0 9 500 -1)", "<IndexedFaceSet",
       "IndexedFaceSet coordIndex: expected -1 or an index in [0, 390), got 500"},
      {R"(containerField="skinCoord")", R"(containerField="coord")", "<HAnimHumanoid",
       "HAnimHumanoid: expected a Coordinate with containerField='skinCoord' (the skin's points), "
       "found none"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.to);
    const std::string text = edited(c.from, c.to);
    EXPECT_EQ(parse_error(text),
              "joe.x3d:" + std::to_string(line_of(text, c.line_of)) + ": " + c.message);
  }
}

TEST(X3dHumanoid, FileWithoutHumanoidOrWithTwoIsAnError) {
  EXPECT_EQ(parse_error("<X3D><Scene/></X3D>"), "joe.x3d:1: expected an HAnimHumanoid, found none");
  const std::string two = edited("</Scene>", "<HAnimHumanoid/>\n</Scene>");
  EXPECT_EQ(parse_error(two), "joe.x3d:" + std::to_string(line_of(two, "<HAnimHumanoid/>")) +
                                  ": expected one HAnimHumanoid, found 2 (a second one here)");
}

TEST(X3dHumanoid, CommandsRefuseABadBodyAndWriteNothing) {
  testing::TempDir dir;
  const auto bad = dir / "bad.x3d";
  write_text_atomic(bad, joe_text().substr(0, joe_text().size() / 2));
  std::string out;
  EXPECT_EQ(testing::run_simcap("model info --body " + bad.string(), &out), 1);
  EXPECT_NE(out.find(bad.string() + ":"), out.npos) << out;
  EXPECT_NE(out.find("not well-formed XML"), out.npos) << out;
  write_text_atomic(dir / "scene.yaml",
                    "actors:\n  - body: {x3d: bad.x3d}\n"
                    "    motion: {procedural: stand, duration: 0.1}\n");
  EXPECT_EQ(testing::run_simcap("render " + (dir / "scene.yaml").string() + " -o " +
                                    (dir / "out").string() + " --quiet",
                                &out),
            1);
  EXPECT_NE(out.find("not well-formed XML"), out.npos) << out;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(X3dHumanoid, MissingFileIsAnError) {
  const std::string e = error_of([] { read_x3d_humanoid("/nonexistent/joe.x3d"); });
  EXPECT_NE(e.find("/nonexistent/joe.x3d"), e.npos) << e;
}

}  // namespace
}  // namespace simcap
