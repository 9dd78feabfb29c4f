// The parts' colours: which parts a silhouette pixel may show, learned on one pose and used on
// another, and the refinement placing a forearm held in front of the torso with them.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tracker/moschini/appearance.h"
#include "tracker/moschini/pose_refiner.h"

namespace simcap::tracker {
namespace {

using testing::Palette;
using testing::silhouette_rays;

constexpr std::array<std::uint8_t, 3> kShirt = {170, 70, 40}, kSkin = {120, 150, 210},
                                      kTrousers = {95, 75, 60};
// Short sleeves: the chest and upper arms wear the shirt, the head, forearms and hands are bare,
// the trousers cover the pelvis and the legs (and the feet: no shoes).
constexpr Palette kDressed = {kTrousers, kShirt,    kSkin,     kShirt,    kSkin,
                              kSkin,     kShirt,    kSkin,     kSkin,     kTrousers,
                              kTrousers, kTrousers, kTrousers, kTrousers, kTrousers};

const StickModel& body() {
  static const StickModel model(testing::capsule_body(), JointSet::urdf);
  return model;
}

std::vector<SilhouetteRay> dressed_rays(const StickPose& pose, std::vector<int>* shown = nullptr,
                                        const Palette& palette = kDressed) {
  return silhouette_rays(body(), testing::capsule_surface(), pose, 3, &palette, shown);
}

AppearanceModel learned(const Palette& palette = kDressed) {
  return {body(), testing::capsule_surface(), testing::walking_pose(),
          dressed_rays(testing::walking_pose(), nullptr, palette)};
}

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
  const AppearanceModel appearance = learned();
  EXPECT_EQ(appearance.learned_parts(), 9) << "every kind of part, left and right together";
  std::vector<int> shown;
  const auto rays = dressed_rays(arm_across(), &shown);
  ASSERT_GT(rays.size(), 1000u);
  const std::uint16_t legs = bits({kPelvis, kLThigh, kLCalf, kLFoot, kRThigh, kRCalf, kRFoot});
  const std::uint16_t bare = bits({kHead, kLForearm, kLHand, kRForearm, kRHand});
  const std::uint16_t shirt = bits({kChest, kLUpperArm, kRUpperArm});
  int missed = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const std::uint16_t parts = appearance.parts(rays[i].colour);
    if (!(parts >> shown[i] & 1)) ++missed;
    const auto& colour = kDressed[shown[i]];
    // Each material rules out the parts that never wear it.
    const std::uint16_t ruled_out = colour == kSkin    ? shirt | legs
                                    : colour == kShirt ? bare | legs
                                                       : static_cast<std::uint16_t>(~legs);
    EXPECT_EQ(parts & ruled_out, 0) << "ray " << i << " shows " << segment_name(shown[i]);
  }
  EXPECT_EQ(missed, 0) << "rays whose colour ruled out the part they show";
}

TEST(AppearanceModel, RulesNothingOutWithoutEvidence) {
  EXPECT_EQ(AppearanceModel().parts({10, 200, 30}), kAllParts);
  Palette plain;
  plain.fill(kShirt);
  EXPECT_EQ(learned(plain).parts(kShirt), kAllParts) << "every part wears the shirt";
  const AppearanceModel dressed = learned();
  EXPECT_EQ(dressed.parts({20, 200, 20}), kAllParts) << "a colour no part wears (a foot, a prop)";
  EXPECT_EQ(dressed.parts({20, 20, 25}), kAllParts) << "too dark to have a chromaticity";
}

// Learned on a frame where the bare parts were seen by a few rays only (views where someone
// else touches the person are left out): the skin is still the person's, not someone else's.
TEST(AppearanceModel, AMaterialOfTheOwnRaysIsNeverForeign) {
  std::vector<int> shown;
  const std::vector<SilhouetteRay> all = dressed_rays(testing::walking_pose(), &shown);
  std::vector<SilhouetteRay> few;
  std::array<int, kSegmentCount> taken{};
  for (size_t i = 0; i < all.size(); ++i) {
    if (kDressed[shown[i]] != kSkin || ++taken[shown[i]] <= 8) few.push_back(all[i]);
  }
  AppearanceModel appearance(body(), testing::capsule_surface(), testing::walking_pose(), few);
  EXPECT_EQ(appearance.learned_parts(), 6) << "head, forearms and hands too few rays to learn";
  EXPECT_EQ(appearance.parts(kSkin), kAllParts) << "no learned part wears the skin";
  constexpr std::array<std::uint8_t, 3> kTheirShirt = {30, 40, 200};
  appearance.learn_others(std::vector<std::array<std::uint8_t, 3>>(100, kTheirShirt));
  EXPECT_FALSE(appearance.foreign(kSkin));
  EXPECT_TRUE(appearance.distinct(kSkin));
  EXPECT_FALSE(appearance.foreign(kShirt));
  EXPECT_TRUE(appearance.foreign(kTheirShirt));
  EXPECT_FALSE(appearance.distinct(kTheirShirt));
}

TEST(PoseRefiner, ColouredRaysPlaceAForearmInFrontOfTheTorso) {
  const StickModel& model = body();
  const StickPose truth = arm_across();
  const AppearanceModel appearance = learned();
  // Two cameras in front of the body and two behind it: from there the forearm lies inside the
  // torso's silhouette.
  const StickGeometry g = model.geometry(truth);
  const Eigen::Vector3d front = 0.5 * (g.proximal[kLForearm] + g.distal[kLForearm]) - truth.t0;
  const double azimuth = std::atan2(front.x(), front.z());
  IcpTargets plain, coloured;
  plain.rays = silhouette_rays(model, testing::capsule_surface(), truth, 3, &kDressed, nullptr,
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
  const PoseRefiner refiner(model, testing::capsule_surface(),
                            testing::converging_without_priors());
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
