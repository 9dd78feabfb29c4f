// Linear-blend skinning: rigid motions are reproduced exactly, an elbow moves only its arm, and the
// parallel float skinner agrees with a plain double-precision reference.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <numbers>
#include <random>

#include "core/error.h"
#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "models/pose.h"

namespace simcap {
namespace {

class SkinningTest : public ::testing::Test {
 protected:
  SkinningTest() : skeleton_(build_humanoid()), mesh_(build_body_mesh(skeleton_)) {}

  std::vector<Eigen::Vector3d> skin(const Pose& pose) const {
    const Skinner skinner(skeleton_, mesh_);
    std::vector<float> buffer(3 * mesh_.vertices.size() + 1, -1.0f);
    skinner.skin(forward_kinematics(skeleton_, pose), buffer.data());
    EXPECT_EQ(buffer.back(), 0.0f);  // Embree's padding is written, not left as garbage
    std::vector<Eigen::Vector3d> out(mesh_.vertices.size());
    for (size_t i = 0; i < out.size(); ++i) {
      out[i] = {buffer[3 * i], buffer[3 * i + 1], buffer[3 * i + 2]};
    }
    return out;
  }

  Eigen::Vector3d neutral(size_t i) const { return mesh_.vertices[i].cast<double>(); }

  Skeleton skeleton_;
  BodyMesh mesh_;
};

TEST_F(SkinningTest, NeutralPoseGivesTheNeutralMesh) {
  const auto v = skin(Pose::neutral(skeleton_));
  for (size_t i = 0; i < v.size(); ++i) ASSERT_LT((v[i] - neutral(i)).norm(), 1e-6) << i;
}

TEST_F(SkinningTest, RootTranslationMovesEveryVertexByIt) {
  Pose pose = Pose::neutral(skeleton_);
  const Eigen::Vector3d shift(0.7, -0.05, 1.3);
  pose.root_position += shift;
  const auto v = skin(pose);
  for (size_t i = 0; i < v.size(); ++i) ASSERT_LT((v[i] - neutral(i) - shift).norm(), 1e-5) << i;
}

TEST_F(SkinningTest, RootRotationMovesTheBodyRigidly) {
  Pose pose = Pose::neutral(skeleton_);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.1, Eigen::Vector3d(0.2, 1.0, -0.3).normalized()));
  pose.rotations[0] = q;
  pose.root_position += Eigen::Vector3d(-1.0, 0.2, 0.4);
  const Eigen::Vector3d root = skeleton_[0].center;
  const auto v = skin(pose);
  for (size_t i = 0; i < v.size(); ++i) {
    const Eigen::Vector3d expected = pose.root_position + q * (neutral(i) - root);
    ASSERT_LT((v[i] - expected).norm(), 1e-5) << i;
  }
}

TEST_F(SkinningTest, BendingTheLeftElbowMovesOnlyTheLeftArmAndHand) {
  Pose pose = Pose::neutral(skeleton_);
  const int elbow = skeleton_.require("l_elbow");
  const Eigen::Quaterniond bend(
      Eigen::AngleAxisd(-0.5 * std::numbers::pi, Eigen::Vector3d::UnitX()));
  pose.rotations[elbow] = bend;
  const auto v = skin(pose);
  const std::set<int> arm = {skeleton_.require("l_shoulder"), elbow,
                             skeleton_.require("l_radiocarpal")};
  const Eigen::Vector3d centre = skeleton_[elbow].center;
  int moved_rigidly = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const int segment = mesh_.vertex_segment[i];
    if (!arm.count(segment)) {
      ASSERT_LT((v[i] - neutral(i)).norm(), 1e-6) << skeleton_[segment].name << " vertex " << i;
      continue;
    }
    // Vertices skinned to the forearm and hand only turn about the elbow centre as one body.
    bool below_elbow = true;
    for (int k = 0; k < 4; ++k) {
      const int j = mesh_.influence_joint[i][k];
      if (mesh_.influence_weight[i][k] > 0 && j != elbow &&
          j != skeleton_.require("l_radiocarpal")) {
        below_elbow = false;
      }
    }
    if (below_elbow) {
      ASSERT_LT((v[i] - (centre + bend * (neutral(i) - centre))).norm(), 1e-5) << i;
      ++moved_rigidly;
    }
  }
  EXPECT_GT(moved_rigidly, 500);
}

TEST_F(SkinningTest, MatchesADoublePrecisionReferenceInAnyPose) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-0.8, 0.8);
  Pose pose = Pose::neutral(skeleton_);
  for (auto& q : pose.rotations) {
    q = Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()) *
        Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()) *
        Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitZ());
  }
  pose.root_position += Eigen::Vector3d(0.3, 0.0, -0.2);
  const auto world = forward_kinematics(skeleton_, pose);
  const auto v = skin(pose);
  for (size_t i = 0; i < v.size(); ++i) {
    Eigen::Vector3d expected = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) {
      const int j = mesh_.influence_joint[i][k];
      expected += mesh_.influence_weight[i][k] *
                  (world[j] * (neutral(i) - skeleton_[j].center));  // bind frames are translations
    }
    ASSERT_LT((v[i] - expected).norm(), 1e-5) << i;
  }
}

TEST_F(SkinningTest, OneThreadAndManyGiveIdenticalBytes) {
  Pose pose = Pose::neutral(skeleton_);
  pose.rotations[skeleton_.require("r_knee")] = Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitX());
  const Skinner skinner(skeleton_, mesh_);
  const auto world = forward_kinematics(skeleton_, pose);
  std::vector<float> parallel(3 * mesh_.vertices.size() + 1), serial(parallel.size());
  skinner.skin(world, parallel.data());
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    skinner.skin(world, serial.data());
  }
  EXPECT_EQ(parallel, serial);
  EXPECT_EQ(skinner.vertex_count(), static_cast<int>(mesh_.vertices.size()));
}

TEST_F(SkinningTest, RejectsMismatchedInputs) {
  const Skinner skinner(skeleton_, mesh_);
  std::vector<float> buffer(3 * mesh_.vertices.size() + 1);
  std::vector<Eigen::Isometry3d> too_few(3, Eigen::Isometry3d::Identity());
  EXPECT_THROW(skinner.skin(too_few, buffer.data()), Error);
  BodyMesh broken = mesh_;
  broken.influence_joint[10][0] = static_cast<std::uint16_t>(skeleton_.size());
  EXPECT_THROW(Skinner(skeleton_, broken), Error);
  broken.influence_weight.pop_back();
  EXPECT_THROW(Skinner(skeleton_, broken), Error);
}

}  // namespace
}  // namespace simcap
