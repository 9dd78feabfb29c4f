// `simcap model`: info, urdf, mesh (read back with Assimp's importer), limits (the shipped table
// is what the program prints), and errors for bad arguments.
#include <gtest/gtest.h>

#include <assimp/scene.h>
#include <urdf_parser/urdf_parser.h>
#include <assimp/Importer.hpp>

#include "core/atomic_file.h"
#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::run_simcap;
using testing::TempDir;

struct LoadedMesh {
  size_t vertices = 0, faces = 0, meshes = 0;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = Eigen::Vector3d::Constant(-1e9);
};

LoadedMesh load(const std::filesystem::path& path) {
  Assimp::Importer importer;
  // The files hold triangles only: read them as they are, without post-processing.
  const aiScene* scene = importer.ReadFile(path.string(), 0);
  LoadedMesh out;
  if (!scene) return out;
  out.meshes = scene->mNumMeshes;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    out.vertices += mesh->mNumVertices;
    out.faces += mesh->mNumFaces;
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const Eigen::Vector3d p(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
      out.lo = out.lo.cwiseMin(p);
      out.hi = out.hi.cwiseMax(p);
    }
  }
  return out;
}

TEST(ModelCli, InfoListsJointsSegmentsAndLengths) {
  std::string out;
  ASSERT_EQ(run_simcap("model info --height 1.60", &out), 0) << out;
  EXPECT_NE(out.find("height 1.600 m"), std::string::npos) << out;
  EXPECT_NE(out.find("l_elbow"), std::string::npos);
  EXPECT_NE(out.find("l_forearm"), std::string::npos);
  EXPECT_NE(out.find("l_elbow_flexion"), std::string::npos);
  // The upper arm length (shoulder -> elbow) is printed on the elbow's row.
  const Skeleton s = build_humanoid({.height = 1.6, .proportions = {}});
  char length[16];
  std::snprintf(length, sizeof length, "%.4f", s.offset(s.require("l_elbow")).norm());
  const size_t row = out.find(" l_elbow ");
  ASSERT_NE(row, std::string::npos);
  EXPECT_NE(out.substr(row, out.find('\n', row) - row).find(length), std::string::npos) << out;
  EXPECT_NE(out.find("triangles"), std::string::npos);
}

TEST(ModelCli, UrdfIsWrittenAndParses) {
  TempDir dir;
  std::string out;
  ASSERT_EQ(run_simcap("model urdf -o " + (dir / "sub/body.urdf").string() + " --height 1.9", &out),
            0)
      << out;
  const auto model = urdf::parseURDF(read_text(dir / "sub/body.urdf"));
  ASSERT_TRUE(model);
  EXPECT_TRUE(model->getJoint("r_shoulder_twist"));
  // The shoulder lies at the height's scale.
  const auto& p = model->getJoint("l_hip_abduction")->parent_to_joint_origin_transform.position;
  const Skeleton s = build_humanoid({.height = 1.9, .proportions = {}});
  EXPECT_NEAR(p.x, s.offset(s.require("l_hip")).x(), 1e-12);
}

TEST(ModelCli, MeshExportsReadBackWithAssimp) {
  TempDir dir;
  const BodyMesh body = build_body_mesh(build_humanoid());
  for (const char* name : {"body.obj", "body.ply", "body.glb"}) {
    std::string out;
    ASSERT_EQ(run_simcap("model mesh -o " + (dir / name).string(), &out), 0) << out;
    const LoadedMesh m = load(dir / name);
    EXPECT_EQ(m.faces, body.triangles.size()) << name;
    // PLY has no sub-meshes: its regions survive as vertex colours only.
    EXPECT_EQ(m.meshes, std::string(name) == "body.ply" ? 1u : size_t{kMaterialRegionCount})
        << name;
    EXPECT_NEAR(m.hi.y(), 1.75, 1e-3) << name;
    EXPECT_NEAR(m.lo.y(), 0.0, 1e-3) << name;
  }
  EXPECT_TRUE(std::filesystem::exists(dir / "body.mtl"));
  // Nothing but the outputs is left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 4);
}

TEST(ModelCli, MeshCanBePosed) {
  TempDir dir;
  std::string out;
  ASSERT_EQ(run_simcap("model mesh -o " + (dir / "up.ply").string() +
                           " --set l_shoulder_abduction=170 --set r_shoulder_abduction=-170",
                       &out),
            0)
      << out;
  // Both arms raised above the head: the hands are the highest points.
  EXPECT_GT(load(dir / "up.ply").hi.y(), 1.75 + 0.2);
  ASSERT_EQ(run_simcap("model mesh -o " + (dir / "walk.glb").string() +
                           " --procedural walk_path --time 0.5",
                       &out),
            0)
      << out;
  EXPECT_GT(load(dir / "walk.glb").faces, 0u);
  // A value outside the limits is applied with a warning.
  ASSERT_EQ(
      run_simcap("model mesh -o " + (dir / "odd.obj").string() + " --set l_knee_flexion=-30", &out),
      0);
  EXPECT_NE(out.find("outside its limits"), std::string::npos) << out;
}

TEST(ModelCli, BadArgumentsFailWithoutOutput) {
  TempDir dir;
  std::string out;
  EXPECT_EQ(run_simcap("model mesh -o " + (dir / "body.stl").string(), &out), 1);
  EXPECT_NE(out.find("body.stl"), std::string::npos) << out;
  EXPECT_EQ(run_simcap("model mesh -o " + (dir / "a.obj").string() + " --set l_wing=3", &out), 1);
  EXPECT_NE(out.find("l_wing"), std::string::npos) << out;
  EXPECT_EQ(run_simcap("model mesh -o " + (dir / "b.obj").string() + " --set l_knee_flexion", &out),
            1);
  EXPECT_NE(run_simcap("model urdf", &out), 0);
  EXPECT_NE(run_simcap("model info --height 7", &out), 0);
  EXPECT_EQ(
      run_simcap("model mesh -o " + (dir / "c.obj").string() + " --procedural walk_path --time 99",
                 &out),
      1);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(ModelCli, ShippedLimitTableIsCurrent) {
  std::string out;
  ASSERT_EQ(run_simcap("model limits", &out), 0);
  EXPECT_EQ(out, read_text(std::filesystem::path(SIMCAP_SOURCE_DIR) / "models/joint_limits.md"))
      << "regenerate with: simcap model limits -o models/joint_limits.md";
}

TEST(ModelCli, ShippedJointNameTablesAreCurrent) {
  std::string out;
  ASSERT_EQ(run_simcap("model joint-names", &out), 0) << out;
  EXPECT_EQ(out, read_text(std::filesystem::path(SIMCAP_SOURCE_DIR) / "models/joint_names.md"))
      << "regenerate with: simcap model joint-names -o models/joint_names.md";
}

TEST(ModelCli, ShippedLimitsUrdfIsWhatModelUrdfWrites) {
  TempDir dir;
  std::string out;
  ASSERT_EQ(run_simcap("model urdf -o " + (dir / "h.urdf").string(), &out), 0) << out;
  EXPECT_EQ(read_text(dir / "h.urdf"), read_text(humanoid_limits_urdf()))
      << "regenerate with: simcap model urdf -o models/assets/humanoid_limits.urdf";
}

TEST(ModelCli, HelpShowsExamples) {
  for (const char* sub : {"info", "urdf", "mesh", "limits"}) {
    std::string out;
    EXPECT_EQ(run_simcap(std::string("model ") + sub + " --help", &out), 0);
    EXPECT_NE(out.find("Example"), std::string::npos) << sub;
  }
}

}  // namespace
}  // namespace simcap
