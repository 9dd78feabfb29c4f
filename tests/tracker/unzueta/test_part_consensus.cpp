// The multiview part consensus (part_consensus.h) against pixels projected by OpenCV
// (cv::projectPoints with each camera's lens distortion): exact views give the point back, views
// whose tracks slid onto another limb are found and left out, and a pair that disagrees with
// itself yields nothing.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <random>

#include "tests/tracker/unzueta/corner_cameras.h"
#include "tracker/unzueta/part_consensus.h"

namespace simcap::tracker {
namespace {

std::vector<PixelObservation> views_of(const std::vector<Camera>& cams, const Eigen::Vector3d& x) {
  std::vector<PixelObservation> views;
  for (const Camera& c : cams) views.push_back({&c, opencv_pixel(c, x)});
  return views;
}

TEST(PartConsensus, ExactViewsGiveThePointBack) {
  const auto cams = corner_cameras();
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.8, 0.8);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d x(u(rng), 1.0 + u(rng), u(rng));
    const auto c = part_consensus(views_of(cams, x));
    ASSERT_TRUE(c) << "trial " << trial;
    EXPECT_LT((c->position - x).norm(), 1e-6) << "trial " << trial;
    EXPECT_EQ(c->inliers, 4);
  }
}

// Tracks that slid 40-60 px (onto another limb, in random directions), one of four cameras or
// two of five: the cameras that agree give the point, and the consensus names the others. (Two
// of four is a tie the views alone cannot break.)
TEST(PartConsensus, TracksOnAnotherLimbAreLeftOut) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.8, 0.8), angle(0, 6.283);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = trial % 2 ? 5 : 4;
    const auto cams = corner_cameras(n);
    const Eigen::Vector3d x(u(rng), 1.0 + u(rng), u(rng));
    auto views = views_of(cams, x);
    for (auto& v : views) v.pixel += Eigen::Vector2d(noise(rng), noise(rng));
    const int a = trial % n, b = n == 5 ? (a + 1 + trial / 5 % 4) % n : a;
    for (int bad = 0; bad < n; ++bad) {
      if (bad != a && bad != b) continue;
      const double t = angle(rng);
      views[bad].pixel += (40 + 10 * (bad % 3)) * Eigen::Vector2d(std::cos(t), std::sin(t));
    }
    const auto c = part_consensus(views);
    ASSERT_TRUE(c) << "trial " << trial;
    for (int k = 0; k < n; ++k) EXPECT_EQ(c->inlier[k], k != a && k != b) << "trial " << trial;
    EXPECT_EQ(c->inliers, 3);
    // Views 1 px off put a part 3-4 m away within a few centimetres.
    EXPECT_LT((c->position - x).norm(), 0.03) << "trial " << trial;
    // The point reprojects (OpenCV's projection) onto the views it kept.
    for (int k = 0; k < n; ++k) {
      if (!c->inlier[k]) continue;
      EXPECT_LT((opencv_pixel(cams[k], c->position) - views[k].pixel).norm(), 3.0);
    }
  }
}

TEST(PartConsensus, NeedsTwoViewsThatAgree) {
  const auto cams = corner_cameras();
  const Eigen::Vector3d x(0.1, 1.2, -0.3), y(0.5, 0.4, 0.4);
  auto views = views_of(cams, x);
  EXPECT_FALSE(part_consensus({views[0]}));
  EXPECT_FALSE(part_consensus({}));
  // Two cameras that see different points whose rays pass far apart.
  const std::vector<PixelObservation> apart{views[0], {&cams[1], opencv_pixel(cams[1], y)}};
  EXPECT_FALSE(part_consensus(apart));
  // With a tolerance wider than their disagreement they are accepted.
  EXPECT_TRUE(part_consensus(apart, {500.0}));
}

}  // namespace
}  // namespace simcap::tracker
