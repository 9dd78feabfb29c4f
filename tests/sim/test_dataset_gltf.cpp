// `simcap export DATASET -o scene.glb` read back by Assimp's glTF importer: the cameras sit and
// look where the calibration says, and the animated joints pass through gt/joints3d.csv.
#include <gtest/gtest.h>

#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <assimp/Importer.hpp>
#include <map>

#include "core/calibration.h"
#include "core/csv.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {
namespace fs = std::filesystem;
using testing::run_simcap;
using testing::TempDir;

constexpr int kFrames = 4;

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return e;
}

struct Animation {
  std::map<std::string, const aiNodeAnim*> channels;
  double ticks_per_frame = 1;
};

// The key of `keys` for the frame at `tick`; the reader may drop a key that repeats its
// predecessor, so the last key up to half a frame after it.
template <class Key>
const Key& key_at(const Key* keys, unsigned count, double tick, double half_frame) {
  unsigned i = 0;
  while (i + 1 < count && keys[i + 1].mTime <= tick + half_frame) ++i;
  return keys[i];
}

// World transform of `node` with each animated node's local transform taken from its keys at
// dataset frame `f`.
Eigen::Matrix4d world_at(const aiNode* node, const Animation& anim, int f) {
  Eigen::Matrix4d local = to_eigen(node->mTransformation);
  const auto it = anim.channels.find(node->mName.C_Str());
  if (it != anim.channels.end()) {
    const aiNodeAnim* a = it->second;
    const double tick = f * anim.ticks_per_frame;
    if (a->mNumRotationKeys > 0) {
      const aiQuaternion& q =
          key_at(a->mRotationKeys, a->mNumRotationKeys, tick, anim.ticks_per_frame / 2).mValue;
      local.topLeftCorner<3, 3>() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix();
    }
    if (a->mNumPositionKeys > 0) {
      const aiVector3D& p =
          key_at(a->mPositionKeys, a->mNumPositionKeys, tick, anim.ticks_per_frame / 2).mValue;
      local.topRightCorner<3, 1>() = Eigen::Vector3d(p.x, p.y, p.z);
    }
  }
  return node->mParent ? world_at(node->mParent, anim, f) * local : local;
}

TEST(DatasetGltf, CamerasAndAnimatedJointsMatchTheDataset) {
  TempDir dir;
  const fs::path d = dir / "d", glb = dir / "scene.glb";
  std::string log;
  ASSERT_EQ(run_simcap("render " SIMCAP_SOURCE_DIR "/scenes/occluders.yaml -o " + d.string() +
                           " -q --set 'rig.resolution=[160,120]' --set render.first_frame=60"
                           " --frames " +
                           std::to_string(kFrames),
                       &log),
            0)
      << log;
  ASSERT_EQ(run_simcap("export " + d.string() + " -o " + glb.string(), &log), 0) << log;

  Assimp::Importer importer;
  const aiScene* scene = importer.ReadFile(glb.string(), 0);
  ASSERT_TRUE(scene) << importer.GetErrorString();

  const auto cams = read_opencv_calibration(d / "calibration" / "opencv.yaml");
  ASSERT_EQ(scene->mNumCameras, cams.size());
  for (const Camera& cam : cams) {
    SCOPED_TRACE(cam.name);
    const aiNode* node = scene->mRootNode->FindNode(cam.name.c_str());
    ASSERT_TRUE(node);
    const Eigen::Matrix4d world = world_at(node, Animation{}, 0);
    EXPECT_LT((world.topRightCorner<3, 1>() - cam.centre()).norm(), 1e-6);
    // glTF cameras look down -Z with +Y up; OpenCV's down +Z with +Y down.
    const Eigen::Matrix3d rot = world.topLeftCorner<3, 3>();
    EXPECT_LT((rot * -Eigen::Vector3d::UnitZ() - cam.R.transpose().col(2)).norm(), 1e-6);
    EXPECT_LT((rot * Eigen::Vector3d::UnitY() + cam.R.transpose().col(1)).norm(), 1e-6);
    const aiCamera* c = nullptr;
    for (unsigned i = 0; i < scene->mNumCameras; ++i) {
      if (cam.name == scene->mCameras[i]->mName.C_Str()) c = scene->mCameras[i];
    }
    ASSERT_TRUE(c);
    EXPECT_NEAR(c->mAspect, static_cast<double>(cam.width) / cam.height, 1e-5);
  }

  // The skinned body and its animation: every truth joint at every frame.
  unsigned rigged = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) rigged += scene->mMeshes[m]->mNumBones > 0;
  EXPECT_GT(rigged, 0u);
  ASSERT_EQ(scene->mNumAnimations, 1u);
  Animation anim;
  const aiAnimation* a = scene->mAnimations[0];
  for (unsigned i = 0; i < a->mNumChannels; ++i) {
    anim.channels[a->mChannels[i]->mNodeName.C_Str()] = a->mChannels[i];
  }
  // 30 frames a second, in the reader's ticks.
  anim.ticks_per_frame = (a->mTicksPerSecond > 0 ? a->mTicksPerSecond : 1.0) / 30.0;
  CsvReader truth(d / "gt" / "joints3d.csv", {"frame", "joint", "x", "y", "z"});
  int rows = 0;
  while (truth.next()) {
    const int f = static_cast<int>(truth.integer(0));
    const aiNode* node = scene->mRootNode->FindNode(truth.text(1).c_str());
    ASSERT_TRUE(node) << truth.text(1);
    const Eigen::Vector3d expected(truth.number(2), truth.number(3), truth.number(4));
    EXPECT_LT((world_at(node, anim, f).topRightCorner<3, 1>() - expected).norm(), 1e-5)
        << truth.text(1) << " frame " << f;
    ++rows;
  }
  EXPECT_EQ(rows, 27 * kFrames);  // the humanoid's 27 joints
}

TEST(DatasetGltf, MissingTablesAreNamed) {
  TempDir dir;
  std::string log;
  EXPECT_NE(run_simcap("export " + dir.path().string() + " -o " + (dir / "x.glb").string(), &log),
            0);
  EXPECT_NE(log.find("scene.yaml"), std::string::npos) << log;
  EXPECT_FALSE(fs::exists(dir / "x.glb"));
}

}  // namespace
}  // namespace simcap
