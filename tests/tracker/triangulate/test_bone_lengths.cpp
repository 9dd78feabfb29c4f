// The rigid bones of a layout (from the humanoid's hierarchy), their median lengths, and the
// projection of a frame onto them: exact lengths after it, a hand-computed two-point case, and
// the metric of the triangulation information respected.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <set>
#include <string>
#include <utility>

#include "tracker/triangulate/bone_lengths.h"

namespace simcap::tracker {
namespace {

using Frame = std::vector<std::optional<Eigen::Vector3d>>;

TEST(BoneLengths, Coco17LimbsAndPelvisButNotTheShoulders) {
  const KeypointLayout& coco = keypoint_layout(KeypointLayoutId::coco17);
  std::set<std::pair<std::string, std::string>> found;
  for (const Bone& b : rigid_bones(coco)) {
    found.emplace(coco.keypoints[b.a].name, coco.keypoints[b.b].name);
  }
  const std::set<std::pair<std::string, std::string>> expected{
      {"left_shoulder", "left_elbow"}, {"right_shoulder", "right_elbow"},
      {"left_elbow", "left_wrist"},    {"right_elbow", "right_wrist"},
      {"left_hip", "right_hip"},       {"left_hip", "left_knee"},
      {"right_hip", "right_knee"},     {"left_knee", "left_ankle"},
      {"right_knee", "right_ankle"}};
  EXPECT_EQ(found, expected);
}

TEST(BoneLengths, MedianIgnoresSpoiledAndMissingFrames) {
  std::vector<Bone> bones{{0, 1, 0}};
  std::vector<Frame> frames;
  for (const double d : {0.30, 0.31, 0.29, 0.90, 0.30}) {
    frames.push_back({Eigen::Vector3d::Zero(), Eigen::Vector3d(d, 0, 0)});
  }
  frames.push_back({Eigen::Vector3d::Zero(), std::nullopt});
  measure_bone_lengths(bones, frames);
  EXPECT_DOUBLE_EQ(bones[0].length, 0.30);
}

TEST(BoneLengths, TwoPointsMoveHalfTheExcessEachUnderEqualWeights) {
  Frame f{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0, 0)};
  const std::vector<Eigen::Matrix3d> info(2, Eigen::Matrix3d::Identity());
  project_onto_bones(f, info, {{0, 1, 0.4}});
  EXPECT_LT((*f[0] - Eigen::Vector3d(0.05, 0, 0)).norm(), 1e-12);
  EXPECT_LT((*f[1] - Eigen::Vector3d(0.45, 0, 0)).norm(), 1e-12);
}

TEST(BoneLengths, TheBetterKnownPointMovesLess) {
  // Point 0 is pinned 100x harder along x: it takes 1/101 of the correction.
  Frame f{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.5, 0, 0)};
  std::vector<Eigen::Matrix3d> info(2, Eigen::Matrix3d::Identity());
  info[0](0, 0) = 100;
  project_onto_bones(f, info, {{0, 1, 0.4}});
  EXPECT_NEAR(f[0]->x(), 0.1 / 101, 1e-12);
  EXPECT_NEAR(f[1]->x(), 0.5 - 0.1 * 100 / 101, 1e-12);
}

TEST(BoneLengths, PlantedChainRecoversExactLengths) {
  // A leg and an arm sharing nothing, plus a pelvis: noisy joints with anisotropic information.
  const std::vector<Bone> bones{{0, 1, 0.42}, {1, 2, 0.40}, {0, 3, 0.18},
                                {3, 4, 0.42}, {5, 6, 0.30}, {6, 7, 0.25}};
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.02);
  Frame f{Eigen::Vector3d(0.1, 0.9, 0),  Eigen::Vector3d(0.12, 0.5, 0.1),
          Eigen::Vector3d(0.1, 0.1, 0),  Eigen::Vector3d(-0.08, 0.9, 0),
          Eigen::Vector3d(-0.1, 0.5, 0), Eigen::Vector3d(0.2, 1.4, 0),
          Eigen::Vector3d(0.3, 1.15, 0), Eigen::Vector3d(0.35, 0.92, 0.1),
          Eigen::Vector3d(5, 5, 5)};
  for (auto& p : f) *p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  std::vector<Eigen::Matrix3d> info;
  for (size_t k = 0; k < f.size(); ++k) {
    Eigen::Matrix3d a = Eigen::Matrix3d::Random();
    info.push_back(a * a.transpose() + 0.5 * Eigen::Matrix3d::Identity());
  }
  const Eigen::Vector3d alone = *f[8];
  project_onto_bones(f, info, bones);
  for (const Bone& b : bones) EXPECT_NEAR((*f[b.a] - *f[b.b]).norm(), b.length, 1e-9);
  EXPECT_EQ(*f[8], alone);  // in no bone
}

TEST(BoneLengths, MissingKeypointsAndUnknownLengthsAreLeftAlone) {
  Frame f{Eigen::Vector3d(0, 0, 0), std::nullopt, Eigen::Vector3d(0.5, 0, 0)};
  const std::vector<Eigen::Matrix3d> info(3, Eigen::Matrix3d::Identity());
  const Frame before = f;
  project_onto_bones(f, info, {{0, 1, 0.3}, {0, 2, std::numeric_limits<double>::quiet_NaN()}});
  EXPECT_EQ(f, before);
}

}  // namespace
}  // namespace simcap::tracker
