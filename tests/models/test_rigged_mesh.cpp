// Rigged meshes through Assimp: simcap's glTF export of its humanoid and of JoeSkin.x3d read
// back (skeleton, bind pose and skin give the same posed vertices), Mixamo-named bones, the
// same rig converted by Assimp's own exporters to Collada and FBX, units and facing, and bad
// files refused with the file named.
#include <gtest/gtest.h>

#include <assimp/scene.h>

#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <map>
#include <numbers>
#include <random>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/body_gltf.h"
#include "models/body_source.h"
#include "models/joint_limits.h"
#include "models/pose.h"
#include "models/rigged_mesh.h"
#include "models/x3d_humanoid.h"
#include "tests/support/error_of.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::error_of;
using testing::TempDir;

const std::array<Eigen::Vector3f, kMaterialRegionCount> kColors = {
    Eigen::Vector3f(0.8f, 0.6f, 0.5f), Eigen::Vector3f(0.2f, 0.3f, 0.7f),
    Eigen::Vector3f(0.3f, 0.3f, 0.3f), Eigen::Vector3f(0.1f, 0.1f, 0.1f),
    Eigen::Vector3f(0.3f, 0.2f, 0.1f)};

void write_glb(const std::filesystem::path& path, const Body& body, const JointNamer& namer = {}) {
  GltfBuilder gltf;
  add_gltf_body(gltf, "body", body.skeleton, body.mesh, kColors, Pose::neutral(body.skeleton),
                namer);
  gltf.write(path);
}

// A pose of `s` bending `joints` by a few tens of degrees about random axes (seeded).
Pose bent(const Skeleton& s, const std::vector<std::string>& joints) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  Pose p = Pose::neutral(s);
  p.root_position += Eigen::Vector3d(0.3, 0.05, -0.2);
  for (const std::string& j : joints) {
    const Eigen::Vector3d axis(n(rng), n(rng), n(rng));
    p.rotations[s.require(j)] = Eigen::AngleAxisd(0.6, axis.normalized());
  }
  return p;
}

std::vector<Eigen::Vector3f> skinned(const Body& b, const Pose& pose) {
  std::vector<float> out(3 * b.mesh.vertices.size() + 1);
  Skinner(b.skeleton, b.mesh).skin(forward_kinematics(b.skeleton, pose), out.data());
  std::vector<Eigen::Vector3f> v;
  for (size_t i = 0; i < b.mesh.vertices.size(); ++i)
    v.emplace_back(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
  return v;
}

// The same pose (by joint name) on another skeleton; joints it lacks stay neutral.
Pose same_pose(const Skeleton& from, const Pose& pose, const Skeleton& to) {
  Pose p = Pose::neutral(to);
  p.root_position = pose.root_position + (to[0].center - from[0].center);
  for (int j = 0; j < to.size(); ++j) {
    const int k = from.find(to[j].name);
    if (k >= 0) p.rotations[j] = pose.rotations[k];
  }
  return p;
}

// Every vertex of `read` skins to where a vertex of `original` at its bind position does (the
// humanoid's parts overlap, so a position may hold several vertices of different weights).
void expect_same_skinning(const Body& original, const Body& read, const Pose& pose, float tol) {
  // Millimetre cells; a read vertex is compared with the originals within 0.2 mm of it.
  std::multimap<std::array<long, 3>, size_t> cells;
  auto cell = [](const Eigen::Vector3f& v, int dx, int dy, int dz) {
    return std::array<long, 3>{std::lround(v.x() * 1e3f) + dx, std::lround(v.y() * 1e3f) + dy,
                               std::lround(v.z() * 1e3f) + dz};
  };
  for (size_t i = 0; i < original.mesh.vertices.size(); ++i) {
    cells.emplace(cell(original.mesh.vertices[i], 0, 0, 0), i);
  }
  const auto a = skinned(original, pose);
  const auto b = skinned(read, same_pose(original.skeleton, pose, read.skeleton));
  size_t matched = 0;
  for (size_t i = 0; i < read.mesh.vertices.size(); ++i) {
    const Eigen::Vector3f& v = read.mesh.vertices[i];
    float nearest = INFINITY;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -1; dz <= 1; ++dz) {
          const auto [first, last] = cells.equal_range(cell(v, dx, dy, dz));
          for (auto it = first; it != last; ++it) {
            if ((original.mesh.vertices[it->second] - v).norm() > 2e-4f) continue;
            nearest = std::min(nearest, (a[it->second] - b[i]).norm());
          }
        }
      }
    }
    if (nearest == INFINITY) continue;
    ++matched;
    EXPECT_LT(nearest, tol) << "vertex " << i;
  }
  EXPECT_EQ(matched, read.mesh.vertices.size());
}

void expect_same_joints(const Skeleton& original, const Skeleton& read, double tol) {
  for (const Joint& j : read.joints()) {
    const int k = original.find(j.name);
    ASSERT_GE(k, 0) << j.name;
    EXPECT_LT((original[k].center - j.center).norm(), tol) << j.name;
    EXPECT_EQ(original[k].is_site, j.is_site) << j.name;
  }
}

const std::vector<std::string> kLimbs = {"l_knee", "r_hip",        "l_shoulder",   "r_elbow",
                                         "vc7",    "l_talocrural", "r_radiocarpal"};

TEST(RiggedMesh, SimcapsGlbOfItsHumanoidReadsBackAsTheSameBody) {
  TempDir dir;
  const Body body = build_body({});
  write_glb(dir / "h.glb", body);
  const Body read = read_rigged_mesh(dir / "h.glb");
  EXPECT_EQ(read.skeleton.size(), body.skeleton.size());
  expect_same_joints(body.skeleton, read.skeleton, 1e-6);
  EXPECT_EQ(read.mesh.triangles.size(), body.mesh.triangles.size());
  expect_same_skinning(body, read, bent(body.skeleton, kLimbs), 1e-4f);
}

TEST(RiggedMesh, JoeThroughGlbKeepsHisJointsAndSkin) {
  TempDir dir;
  const Body joe = read_x3d_humanoid(SIMCAP_SOURCE_DIR "/models/assets/JoeSkin.x3d");
  write_glb(dir / "joe.glb", joe);
  const Body read = read_rigged_mesh(dir / "joe.glb", {.naming = JointNaming::hanim});
  EXPECT_EQ(read.skeleton.size(), joe.skeleton.size());
  expect_same_joints(joe.skeleton, read.skeleton, 1e-6);
  expect_same_skinning(joe, read, bent(joe.skeleton, kLimbs), 1e-4f);
}

TEST(RiggedMesh, MixamoNamesAreMappedAndOtherBonesFolded) {
  TempDir dir;
  const Body body = build_body({});
  write_glb(dir / "m.glb", body,
            [](const std::string& h) { return joint_name_in(JointNaming::mixamo, h); });
  const Body read = read_rigged_mesh(dir / "m.glb");  // automatic: finds Mixamo's names
  EXPECT_NE(read.notes.front().find("joint names: mixamo"), std::string::npos)
      << read.notes.front();
  EXPECT_EQ(read.skeleton[read.skeleton.require("l_elbow")].parent,
            read.skeleton.require("l_shoulder"));
  EXPECT_LT(read.skeleton.find("vl5"), 0);  // no Mixamo bone: folded into Hips
  expect_same_joints(body.skeleton, read.skeleton, 1e-6);
  // Poses of the joints Mixamo names skin alike.
  expect_same_skinning(body, read, bent(body.skeleton, kLimbs), 1e-4f);
}

// The rig converted by Assimp's own exporter (Collada, FBX) reads back the same.
TEST(RiggedMesh, AssimpsColladaAndFbxOfTheRigReadBack) {
  TempDir dir;
  const Body body = build_body({});
  write_glb(dir / "h.glb", body);
  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile((dir / "h.glb").string(), 0);
  ASSERT_TRUE(scene) << importer.GetErrorString();
  for (const auto& [id, file] : {std::pair{"collada", "h.dae"}, std::pair{"fbxa", "h.fbx"}}) {
    SCOPED_TRACE(file);
    Assimp::Exporter exporter;
    ASSERT_EQ(exporter.Export(scene, id, (dir / file).string()), aiReturn_SUCCESS)
        << exporter.GetErrorString();
    const Body read = read_rigged_mesh(dir / file, {.naming = JointNaming::hanim});
    expect_same_joints(body.skeleton, read.skeleton, 1e-4);
    expect_same_skinning(body, read, bent(body.skeleton, kLimbs), 1e-3f);
  }
}

TEST(RiggedMesh, CentimetresAndAnotherFacingArePutRight) {
  TempDir dir;
  Body body = build_body({});
  // The body in centimetres, facing +X (turned a quarter about +Y), 5 cm above the floor.
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(std::numbers::pi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  Body cm;
  for (const Joint& j : body.skeleton.joints()) {
    Joint c = j;
    c.center = 100 * (turn * j.center) + Eigen::Vector3d(0, 5, 0);
    cm.skeleton.add(c);
  }
  cm.mesh = body.mesh;
  for (auto& v : cm.mesh.vertices) {
    v = (100 * (turn * v.cast<double>()) + Eigen::Vector3d(0, 5, 0)).cast<float>();
  }
  write_glb(dir / "cm.glb", cm);
  const Body read = read_rigged_mesh(dir / "cm.glb");
  expect_same_joints(body.skeleton, read.skeleton, 1e-5);
}

TEST(RiggedMesh, BadFilesAreRefusedNamingTheFile) {
  TempDir dir;
  const Body body = build_body({});
  write_glb(dir / "h.glb", body);
  const std::string glb = read_text(dir / "h.glb");
  write_text_atomic(dir / "cut.glb", glb.substr(0, glb.size() / 2));
  const std::string cut = error_of([&] { read_rigged_mesh(dir / "cut.glb"); });
  EXPECT_EQ(cut.rfind((dir / "cut.glb").string() + ": Assimp cannot read it: ", 0), 0u) << cut;

  GltfBuilder plain;
  GltfBuilder::Vertices v;
  v.positions = body.mesh.vertices;
  std::vector<std::uint32_t> indices;
  for (const auto& t : body.mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());
  GltfBuilder::Node node;
  node.name = "statue";
  node.mesh = plain.add_mesh("statue", v, {{indices, -1}});
  plain.add_node(node);
  plain.write(dir / "plain.glb");
  EXPECT_EQ(
      error_of([&] { read_rigged_mesh(dir / "plain.glb"); }),
      (dir / "plain.glb").string() + ": no mesh of the file has bones (expected a rigged mesh)");

  EXPECT_EQ(error_of([&] { read_rigged_mesh(dir / "h.glb", {.naming = JointNaming::mixamo}); }),
            (dir / "h.glb").string() +
                ": no bone maps to humanoid_root under the mixamo joint names "
                "(models/joint_names.md)");

  // Unknown names for the knees: the required joints are missing.
  write_glb(dir / "knees.glb", body, [](const std::string& h) {
    return h.ends_with("_knee") ? "kneecap_" + h.substr(0, 1) : h;
  });
  const std::string knees = error_of([&] { read_rigged_mesh(dir / "knees.glb"); });
  EXPECT_EQ(knees, (dir / "knees.glb").string() +
                       ": the humanoid lacks H-Anim joints simcap needs: l_knee, r_knee");

  // Two bones named for one joint (Mixamo names match after their prefix).
  write_glb(dir / "twice.glb", body, [](const std::string& h) {
    const std::string name = joint_name_in(JointNaming::mixamo, h);
    return h == "r_elbow" ? std::string("mixamorig1:LeftForeArm") : name;
  });
  EXPECT_EQ(error_of([&] { read_rigged_mesh(dir / "twice.glb"); }),
            (dir / "twice.glb").string() +
                ": bones 'mixamorig:LeftForeArm' and 'mixamorig1:LeftForeArm' both map to H-Anim "
                "joint 'l_elbow'");
}

TEST(RiggedMesh, ModelCommandsReadAndWriteRigs) {
  TempDir dir;
  std::string out;
  ASSERT_EQ(
      testing::run_simcap("model mesh --rig-names mixamo -o " + (dir / "m.glb").string(), &out), 0)
      << out;
  ASSERT_EQ(testing::run_simcap("model info --body " + (dir / "m.glb").string(), &out), 0) << out;
  EXPECT_NE(out.find("joint names: mixamo"), std::string::npos) << out;
  write_text_atomic(dir / "bad.glb", "glTF not really");
  EXPECT_EQ(testing::run_simcap("model info --body " + (dir / "bad.glb").string(), &out), 1);
  EXPECT_NE(out.find("bad.glb: Assimp cannot read it"), std::string::npos) << out;
  // A scene whose actor wears the rig renders; the truth lists its joints.
  write_text_atomic(dir / "scene.yaml",
                    "actors:\n  - body: {mesh: m.glb, joint_map: mixamo}\n"
                    "    motion: {procedural: walk_in_place, duration: 0.1}\n");
  ASSERT_EQ(
      testing::run_simcap("render " + (dir / "scene.yaml").string() + " -o " +
                              (dir / "d").string() + " --quiet --set 'rig.resolution=[64,48]'",
                          &out),
      0)
      << out;
  EXPECT_NE(read_text(dir / "d" / "gt" / "joints3d.csv").find(",l_metatarsophalangeal_2,"),
            std::string::npos);
}

}  // namespace
}  // namespace simcap
