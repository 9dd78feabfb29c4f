// The parts' colours: which parts a silhouette pixel may show, learned on one pose and used on
// another, and the refinement placing a forearm held in front of the torso with them.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/tracker/ray_rig.h"
#include "tests/tracker/refine_test_support.h"
#include "tracker/appearance.h"
#include "tracker/pose_refiner.h"

namespace simcap::tracker {
namespace {

using testing::Palette;
using testing::silhouette_rays;

constexpr std::array<std::uint8_t, 3> kShirt = {170, 70, 40}, kSkin = {120, 150, 210},
                                      kTrousers = {95, 75, 60};
// Short sleeves: the upper arms wear the shirt, the forearms (and hands) are bare.
constexpr Palette kDressed = {kShirt, kSkin,     kShirt,    kSkin,     kShirt,
                              kSkin,  kTrousers, kTrousers, kTrousers, kTrousers};

std::uint16_t bits(std::initializer_list<int> segments) {
  std::uint16_t b = 0;
  for (const int s : segments) b |= 1u << s;
  return b;
}

// Left forearm bent across the front of the torso.
StickPose arm_across() {
  StickPose p = testing::walking_pose();
  p.theta[kLShoulder1] = 0.1;
  p.theta[kLShoulder2] = -0.5;
  p.theta[kLElbow] = -1.8;
  return p;
}

TEST(AppearanceModel, TellsThePartsApartOnAnotherPose) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  const AppearanceModel appearance(model, testing::walking_pose(),
                                   silhouette_rays(model, testing::walking_pose(), 3, &kDressed));
  EXPECT_EQ(appearance.learned_parts(), 6);
  std::vector<int> shown;
  const auto rays = silhouette_rays(model, arm_across(), 3, &kDressed, &shown);
  ASSERT_GT(rays.size(), 1000u);
  const std::uint16_t legs = bits({kLThigh, kLCalf, kRThigh, kRCalf});
  const std::uint16_t forearms = bits({kLForearm, kRForearm});
  const std::uint16_t shirt = bits({kTorso, kLUpperArm, kRUpperArm});
  int missed = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const std::uint16_t parts = appearance.parts(rays[i].colour);
    if (!(parts >> shown[i] & 1)) ++missed;
    const auto& colour = kDressed[shown[i]];
    // Each material rules out the parts that never wear it.
    const std::uint16_t ruled_out = colour == kSkin    ? shirt | legs
                                    : colour == kShirt ? forearms | legs
                                                       : static_cast<std::uint16_t>(~legs);
    EXPECT_EQ(parts & ruled_out, 0) << "ray " << i << " shows " << segment_name(shown[i]);
  }
  EXPECT_EQ(missed, 0) << "rays whose colour ruled out the part they show";
}

TEST(AppearanceModel, RulesNothingOutWithoutEvidence) {
  EXPECT_EQ(AppearanceModel().parts({10, 200, 30}), kAllParts);
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  Palette plain;
  plain.fill(kShirt);
  const AppearanceModel one_colour(model, testing::walking_pose(),
                                   silhouette_rays(model, testing::walking_pose(), 3, &plain));
  EXPECT_EQ(one_colour.parts(kShirt), kAllParts) << "every part wears the shirt";
  const AppearanceModel dressed(model, testing::walking_pose(),
                                silhouette_rays(model, testing::walking_pose(), 3, &kDressed));
  EXPECT_EQ(dressed.parts({20, 200, 20}), kAllParts) << "a colour no part wears (a foot, a prop)";
  EXPECT_EQ(dressed.parts({20, 20, 25}), kAllParts) << "too dark to have a chromaticity";
}

TEST(PoseRefiner, ColouredRaysPlaceAForearmInFrontOfTheTorso) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  const StickPose truth = arm_across();
  const AppearanceModel appearance(model, testing::walking_pose(),
                                   silhouette_rays(model, testing::walking_pose(), 3, &kDressed));
  // Two cameras in front of the body and two behind it: from there the forearm lies inside the
  // torso's silhouette.
  const StickGeometry g = model.geometry(truth);
  const Eigen::Vector3d front = 0.5 * (g.proximal[kLForearm] + g.distal[kLForearm]) -
                                0.5 * (g.proximal[kTorso] + g.distal[kTorso]);
  const double azimuth = std::atan2(front.x(), front.z());
  IcpTargets plain, coloured;
  plain.rays = silhouette_rays(model, truth, 3, &kDressed, nullptr,
                               {azimuth - 0.4, azimuth + 0.4, azimuth + 2.7, azimuth + 3.5});
  coloured.rays = plain.rays;
  for (SilhouetteRay& ray : coloured.rays) ray.parts = appearance.parts(ray.colour);
  const auto hand = [&](const StickPose& p) {
    return model.reference_points(model.geometry(p))[kLHandTip];
  };
  // The forearm swung along the torso's front, where its rays still meet the torso.
  StickPose start = truth;
  start.theta[kLElbow] = -1.2;
  ASSERT_GT((hand(start) - hand(truth)).norm(), 0.1);
  const PoseRefiner refiner(model, testing::converging_without_priors());
  StickPose from_plain = start, from_coloured = start;
  refiner.refine(plain, from_plain);
  refiner.refine(coloured, from_coloured);
  const double plain_error = (hand(from_plain) - hand(truth)).norm();
  const double coloured_error = (hand(from_coloured) - hand(truth)).norm();
  EXPECT_LT(coloured_error, 0.03);
  EXPECT_LT(coloured_error, 0.5 * plain_error) << "plain rays: " << plain_error << " m";
}

}  // namespace
}  // namespace simcap::tracker
