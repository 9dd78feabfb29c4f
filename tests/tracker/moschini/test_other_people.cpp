// The person gate with silhouettes that show everyone (person_gate.h): two spheres, the tracked
// person and someone else, seen by a ring of cameras and drawn analytically.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/rig.h"
#include "tests/tracker/moschini/sphere_silhouette.h"
#include "tracker/moschini/person_gate.h"

namespace simcap::tracker {
namespace {

using testing::sphere_silhouette;

// Deep copies (the gate writes into the silhouettes it is given).
std::vector<cv::Mat> copies(const std::vector<cv::Mat>& masks) {
  std::vector<cv::Mat> out;
  for (const cv::Mat& m : masks) out.push_back(m.clone());
  return out;
}

// A body whose every capsule is the sphere at `c`.
PlacedSurface ball(const Eigen::Vector3d& c, double radius) {
  PlacedSurface body;
  for (PlacedCapsule& capsule : body) {
    capsule.a = capsule.centre = c;
    capsule.ra = capsule.bound = radius;
  }
  return body;
}

struct Scene {
  std::vector<Camera> cameras;
  VisualHull hull;
  Scene()
      : cameras(ring_rig(4, {0, 1, 0}, 3.0, 1.5, {320, 240, 0.9})),
        hull(cameras,
             {Eigen::AlignedBox3d(Eigen::Vector3d(-1, 0.4, -1), Eigen::Vector3d(1, 1.6, 1)), 0.02,
              0}) {}
  std::vector<cv::Mat> silhouettes(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
    std::vector<cv::Mat> out;
    for (const Camera& cam : cameras)
      out.push_back(sphere_silhouette(cam, a, 0.2) | sphere_silhouette(cam, b, 0.2));
    return out;
  }
  std::vector<cv::Mat> of(const Eigen::Vector3d& c) const {
    std::vector<cv::Mat> out;
    for (const Camera& cam : cameras) out.push_back(sphere_silhouette(cam, c, 0.2));
    return out;
  }
};

const Eigen::Vector3d kPerson(0, 1, 0);

// The other person stands in front of the tracked one for the +X camera, half overlapping it.
// The tracked body is known only roughly (a smaller ball: the capsules of a real body miss its
// clothes and hair, and it has moved since): the other's pixels over its edge are cover then,
// the person's own pixels stay silhouette. (A body much smaller than the person's outline loses
// the person's pixels beyond GateOptions::core_margin_m where the others' volume projects.)
TEST(OtherPeople, PixelsOnlyTheOthersVolumeExplainsBecomeCover) {
  const Scene scene;
  const Eigen::Vector3d other(0.65, 1, 0.25);
  const std::vector<cv::Mat> all = scene.silhouettes(kPerson, other);
  Occupancy hull;
  scene.hull.carve(all, hull);
  const PlacedSurface body = ball(kPerson, 0.18);
  GateOptions options;
  options.others_to_cover = true;
  // Who is in front is the next test's: here the phantom volume, where the cones through the
  // two cross, lies in front of the person for some cameras and would take 14 % of its pixels
  // (in a capture, the person's colours keep most of those: restrict()'s `distinct`).
  options.front_m = 1.0;
  std::vector<cv::Mat> silhouettes = copies(all), cover;
  const GateResult result =
      PersonGate(scene.cameras, options).restrict(hull, body, silhouettes, &cover);
  EXPECT_TRUE(result.changed);
  EXPECT_GT(result.covered_pixels, 50);
  EXPECT_EQ(result.others.size(), static_cast<size_t>(result.dropped_voxels));
  ASSERT_EQ(cover.size(), all.size());
  const std::vector<cv::Mat> own = scene.of(kPerson), theirs = scene.of(other);
  int covered = 0, theirs_covered = 0, own_pixels = 0, own_lost = 0;
  for (size_t c = 0; c < all.size(); ++c) {
    covered += cv::countNonZero(cover[c]);
    theirs_covered += cv::countNonZero(cover[c] & theirs[c]);
    own_pixels += cv::countNonZero(own[c]);
    own_lost += cv::countNonZero(cover[c] & own[c] & ~theirs[c]);
    // Every cover pixel is someone's: nothing of the background.
    EXPECT_EQ(cv::countNonZero(cover[c] & ~all[c]), 0) << "camera " << c;
  }
  EXPECT_EQ(covered, result.covered_pixels);
  // Mostly the other's pixels; of the person's, a few at its edge where the volume dropped is
  // phantom (the cones through the person and the other cross there): 299 of 6000 here.
  EXPECT_GT(theirs_covered, 2 * own_lost);
  EXPECT_LT(own_lost, 0.06 * own_pixels);
  // Without it, those pixels stay silhouette (and would pull the body towards the other).
  options.others_to_cover = false;
  std::vector<cv::Mat> plain = copies(all);
  const GateResult before = PersonGate(scene.cameras, options).restrict(hull, body, plain, nullptr);
  int others_kept = 0, others_kept_before = 0;
  for (size_t c = 0; c < all.size(); ++c) {
    others_kept += cv::countNonZero(silhouettes[c] & theirs[c] & ~own[c]);
    others_kept_before += cv::countNonZero(plain[c] & theirs[c] & ~own[c]);
  }
  EXPECT_EQ(before.covered_pixels, 0);
  EXPECT_LT(others_kept, others_kept_before - 50);
  // Pixels whose colour says they are the person's are left to the person.
  std::vector<cv::Mat> distinct = copies(all), kept = copies(all), no_cover;
  const GateResult trusted = PersonGate(scene.cameras, {.others_to_cover = true, .front_m = 1.0})
                                 .restrict(hull, body, kept, &no_cover, &distinct);
  EXPECT_EQ(trusted.covered_pixels, 0);
}

// The other person touches the tracked one: one hull component, cut to reach_m of the body,
// keeps the other's near half. Where the other was on the frame before tells that half apart.
TEST(OtherPeople, WhereTheOthersWereKeepsTheirVolumeTheirsWhenTheyTouch) {
  const Scene scene;
  const PlacedSurface body = ball(kPerson, 0.2);
  // Without the rule for someone in front (tested below): the phantom volume of the touching
  // pair lies in front of the person for camera 1 and would cover 144 of its pixels there.
  const GateOptions options{.others_to_cover = true, .front_m = 1.0};
  const PersonGate gate(scene.cameras, options);
  // The frame before: apart.
  const Eigen::Vector3d apart(0.55, 1, 0), touching(0.42, 1, 0);
  std::vector<cv::Mat> silhouettes = scene.silhouettes(kPerson, apart), cover;
  Occupancy hull;
  scene.hull.carve(silhouettes, hull);
  const GateResult first = gate.restrict(hull, body, silhouettes, &cover);
  ASSERT_GT(first.others.size(), 100u);
  // Now touching.
  const std::vector<cv::Mat> all = scene.silhouettes(kPerson, touching);
  scene.hull.carve(all, hull);
  std::vector<cv::Mat> forgetful = copies(all), remembering = copies(all), cover_a, cover_b;
  const GateResult without = gate.restrict(hull, body, forgetful, &cover_a);
  const GateResult with = gate.restrict(hull, body, remembering, &cover_b, nullptr, &first.others);
  EXPECT_GT(with.dropped_voxels, without.dropped_voxels + 100);
  const std::vector<cv::Mat> own = scene.of(kPerson), theirs = scene.of(touching);
  int theirs_without = 0, theirs_with = 0;
  for (size_t c = 0; c < all.size(); ++c) {
    theirs_without += cv::countNonZero(forgetful[c] & theirs[c] & ~own[c]);
    theirs_with += cv::countNonZero(remembering[c] & theirs[c] & ~own[c]);
    EXPECT_EQ(cv::countNonZero(own[c] & ~theirs[c] & ~remembering[c]), 0) << "camera " << c;
  }
  EXPECT_LT(theirs_with, theirs_without / 2);
}

// Someone passes between camera 0 and the tracked person (whose body is known here): where they
// hide the person, their pixels lie inside its outline, and their volume in front of the body
// makes them cover, as ground-truth silhouettes would. From the opposite camera the person hides
// them: its pixels stay its own.
TEST(OtherPeople, SomeoneInFrontOfThePersonIsCoverWhereTheyHideIt) {
  const Scene scene;
  Eigen::Vector3d towards = scene.cameras[0].centre() - kPerson;
  towards.y() = 0;
  towards.normalize();
  const Eigen::Vector3d other = kPerson + 0.55 * towards;
  const std::vector<cv::Mat> all = scene.silhouettes(kPerson, other);
  Occupancy hull;
  scene.hull.carve(all, hull);
  const PlacedSurface body = ball(kPerson, 0.2);
  const auto covered = [&](double front_m) {
    std::vector<cv::Mat> silhouettes = copies(all), cover;
    PersonGate(scene.cameras, {.others_to_cover = true, .front_m = front_m})
        .restrict(hull, body, silhouettes, &cover);
    return cover;
  };
  const std::vector<cv::Mat> cover = covered(GateOptions{}.front_m);
  const std::vector<cv::Mat> own = scene.of(kPerson), theirs = scene.of(other);
  const cv::Mat hiding = theirs[0] & own[0];
  ASSERT_GT(cv::countNonZero(hiding), 500);
  EXPECT_GT(cv::countNonZero(cover[0] & hiding), 0.9 * cv::countNonZero(hiding));
  // With a front_m beyond the gap between them, the body's outline alone decides: they stay the
  // person's pixels.
  EXPECT_LT(cv::countNonZero(covered(1.0)[0] & hiding), 0.1 * cv::countNonZero(hiding));
  size_t opposite = 0;
  for (size_t c = 1; c < scene.cameras.size(); ++c) {
    if ((scene.cameras[c].centre() - kPerson).dot(towards) <
        (scene.cameras[opposite].centre() - kPerson).dot(towards))
      opposite = c;
  }
  EXPECT_LT(cv::countNonZero(cover[opposite] & own[opposite]),
            0.02 * cv::countNonZero(own[opposite]));
}

// Someone stands just behind the person and to its side: from camera 0 their pixels border the
// person's outline. Within the slack the body's outline is widened by (own_margin_m) only the
// motion the body may have made explains them, the other's volume does directly: beyond
// core_margin_m of the outline they are cover.
TEST(OtherPeople, SomeoneBehindThePersonIsCoverBesideItsOutline) {
  const Scene scene;
  const Camera& cam = scene.cameras[0];
  Eigen::Vector3d towards = cam.centre() - kPerson;
  towards.y() = 0;
  towards.normalize();
  const Eigen::Vector3d side = towards.cross(Eigen::Vector3d::UnitY());
  const Eigen::Vector3d other = kPerson - 0.5 * towards + 0.25 * side;
  const std::vector<cv::Mat> all = scene.silhouettes(kPerson, other);
  Occupancy hull;
  scene.hull.carve(all, hull);
  const PlacedSurface body = ball(kPerson, 0.2);
  const GateOptions options{.others_to_cover = true};
  std::vector<cv::Mat> silhouettes = copies(all), cover;
  PersonGate(scene.cameras, options).restrict(hull, body, silhouettes, &cover);
  const cv::Mat own = sphere_silhouette(cam, kPerson, 0.2);
  const cv::Mat band = all[0] &
                       ~sphere_silhouette(cam, kPerson, 0.2 + options.core_margin_m + 0.01) &
                       sphere_silhouette(cam, kPerson, 0.2 + options.own_margin_m - 0.01);
  ASSERT_GT(cv::countNonZero(band), 15);
  EXPECT_GT(cv::countNonZero(cover[0] & band), 0.9 * cv::countNonZero(band));
  EXPECT_EQ(cv::countNonZero(cover[0] & own), 0);
}

}  // namespace
}  // namespace simcap::tracker
