// The multiview left/right checks against pixels projected by OpenCV (cv::projectPoints): a
// camera whose hands are swapped is found from the other cameras' triangulation (and only that
// camera), two parts whose consensus fell on one hand get the other hand back from the cameras
// that still track it, and a track on the other hand's point is named (pair_consensus.h).
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>

#include "tests/tracker/unzueta/corner_cameras.h"
#include "tracker/unzueta/pair_consensus.h"
#include "tracker/unzueta/view_swaps.h"

namespace simcap::tracker {
namespace {

std::vector<PixelObservation> views_of(const std::vector<Camera>& cams,
                                       const std::vector<Eigen::Vector3d>& per_camera) {
  std::vector<PixelObservation> views;
  for (size_t k = 0; k < cams.size(); ++k)
    views.push_back({&cams[k], opencv_pixel(cams[k], per_camera[k])});
  return views;
}

// Four corner cameras see two hands 0.5 m apart, about across the room's X axis (45 degrees
// to every camera's view, so that each camera sees them apart); one camera's labels are exchanged.
// The other three cameras' consensus of each hand names that camera, whose tracks are then swapped
// back.
TEST(ViewSwaps, OneCamerasSwappedHandsAreFoundAndUndone) {
  const auto cams = corner_cameras();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d centre(u(rng), 1.0 + u(rng), u(rng));
    const Eigen::Vector3d across(std::cos(u(rng)), 0.3 * u(rng), std::sin(u(rng)));
    const Eigen::Vector3d l = centre + 0.25 * across.normalized(),
                          r = centre - 0.25 * across.normalized();
    const int bad = trial % 4;
    std::vector<Eigen::Vector3d> on_l(4, l), on_r(4, r);
    std::swap(on_l[bad], on_r[bad]);
    auto left = views_of(cams, on_l), right = views_of(cams, on_r);
    const auto cl = part_consensus(left), cr = part_consensus(right);
    ASSERT_TRUE(cl && cr) << "trial " << trial;
    EXPECT_FALSE(cl->inlier[bad]);
    EXPECT_FALSE(cr->inlier[bad]);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(
          tracks_swapped(cams[k], left[k].pixel, right[k].pixel, cl->position, cr->position, 12.0),
          k == bad)
          << "trial " << trial << " camera " << k;
    }
    std::swap(left[bad].pixel, right[bad].pixel);
    const auto fixed_l = part_consensus(left), fixed_r = part_consensus(right);
    EXPECT_EQ(fixed_l->inliers, 4);
    EXPECT_EQ(fixed_r->inliers, 4);
    EXPECT_LT((fixed_l->position - l).norm(), 1e-6);
    EXPECT_LT((fixed_r->position - r).norm(), 1e-6);
  }
}

// Not a swap: one track slid onto the other hand (the other track kept), and two hands so near
// that the camera cannot tell them apart.
TEST(ViewSwaps, ASlidTrackOrTouchingHandsAreNotSwapped) {
  const auto cams = corner_cameras();
  const Eigen::Vector3d l(0.3, 1.1, 0.1), r(-0.2, 0.9, -0.1);
  const Eigen::Vector2d pl = opencv_pixel(cams[1], l), pr = opencv_pixel(cams[1], r);
  EXPECT_TRUE(tracks_swapped(cams[1], pr, pl, l, r, 12.0));
  EXPECT_FALSE(tracks_swapped(cams[1], pr, pr, l, r, 12.0));
  EXPECT_FALSE(tracks_swapped(cams[1], pl, pr, l, r, 12.0));
  const Eigen::Vector3d near = l + Eigen::Vector3d(0.02, 0, 0);
  EXPECT_FALSE(tracks_swapped(cams[1], opencv_pixel(cams[1], near), pl, l, near, 12.0));
}

// The left hand's flock slid onto the right hand in two cameras of four: those two agree (on
// the right hand's point) as well as the two that still hold the left hand, so the part's own
// consensus is a tie; with the right hand's consensus there, the pair's gives the left
// hand to the two cameras still on it.
TEST(PairConsensus, BothPartsOnOneLimbLeaveTheOtherToTheCamerasOnIt) {
  const auto cams = corner_cameras();
  const Eigen::Vector3d l(0.25, 1.0, 0.2), r(-0.25, 0.95, -0.1);
  const auto left = views_of(cams, {r, r, l, l}), right = views_of(cams, {r, r, r, r});
  const PairConsensus pair = pair_consensus(left, right);
  ASSERT_TRUE(pair.left && pair.right);
  EXPECT_LT((pair.left->position - l).norm(), 1e-6);
  EXPECT_LT((pair.right->position - r).norm(), 1e-6);
  EXPECT_EQ(pair.left->inlier, (std::vector<bool>{false, false, true, true}));
  EXPECT_EQ(pair.right->inliers, 4);
}

// Hands that touch stay one point: no camera tracks either elsewhere.
TEST(PairConsensus, TouchingHandsStayTogether) {
  const auto cams = corner_cameras();
  const Eigen::Vector3d l(0.02, 1.0, 0.0), r(-0.02, 1.0, 0.0);
  const PairConsensus pair =
      pair_consensus(views_of(cams, {l, l, l, l}), views_of(cams, {r, r, r, r}));
  ASSERT_TRUE(pair.left && pair.right);
  EXPECT_LT((pair.left->position - l).norm(), 1e-6);
  EXPECT_LT((pair.right->position - r).norm(), 1e-6);
  // One stray track elsewhere is no consensus.
  const Eigen::Vector3d away(0.5, 1.4, 0.3);
  const PairConsensus stray =
      pair_consensus(views_of(cams, {l, l, l, away}), views_of(cams, {r, r, r, r}));
  EXPECT_LT((stray.left->position - l).norm(), 1e-6);
}

// A left hand whose track sits on the right hand's point, where the left hand was half a metre
// away in the last frame, has slid; on its own point, or where the hands were together, not.
TEST(PairConsensus, ATrackOnTheOtherPartsPointHasSlid) {
  const auto cams = corner_cameras();
  const Eigen::Vector3d l(0.25, 1.0, 0.2), r(-0.25, 0.95, -0.1);
  const Eigen::Vector2d on_r = opencv_pixel(cams[0], r) + Eigen::Vector2d(3, -2);
  EXPECT_TRUE(slid_onto_other(cams[0], on_r, r, l, 12.0));
  EXPECT_FALSE(slid_onto_other(cams[0], opencv_pixel(cams[0], l), r, l, 12.0));
  EXPECT_FALSE(slid_onto_other(cams[0], on_r, r, r + Eigen::Vector3d(0.05, 0, 0), 12.0));
}

}  // namespace
}  // namespace simcap::tracker
