// The limb-end proposals' image side: the geodesic extremities of a synthetic silhouette seen from
// its trunk (the hands, the feet and the head, not the shoulders' corners, not a cut by the
// image's edge), and their assignment to the limbs of the present pose.
#include <gtest/gtest.h>

#include "tracker/gomez/silhouette_ends.h"

namespace simcap::tracker::gomez {
namespace {

// A stick figure at working resolution 80 x 100 (factor 2, crop at (10, 20)): trunk, head, the
// left arm out sideways, the right arm raised, two legs down to row `feet`.
FrameCues stick_figure(int feet) {
  FrameCues cues;
  cues.view = {nullptr, 10, 20, 2, 80, 100};
  cues.cls.assign(80 * 100, 0);
  const auto fill = [&](int u0, int v0, int u1, int v1) {
    for (int v = v0; v <= v1; ++v) {
      for (int u = u0; u <= u1; ++u) cues.cls[v * 80 + u] = 1;
    }
  };
  fill(32, 30, 47, 60);  // trunk
  fill(36, 18, 43, 29);  // head, top row 18
  fill(10, 31, 31, 34);  // left arm out to column 10
  fill(48, 8, 51, 33);   // right arm raised to row 8
  fill(33, 61, 38, feet);
  fill(41, 61, 46, feet);
  return cues;
}

Eigen::Vector2d full(double u, double v) {
  return {10 + (u + 0.5) * 2 - 0.5, 20 + (v + 0.5) * 2 - 0.5};
}

TEST(SilhouetteEnds, TheHandsFeetAndHeadOfAStickFigure) {
  const FrameCues cues = stick_figure(92);
  const std::vector<SilhouetteEnd> ends = silhouette_ends(cues, full(40, 45), 22, 6);
  ASSERT_EQ(ends.size(), 5u);
  // Farthest first: the feet (47+ working px away), then the hands, then the head.
  for (size_t k = 1; k < ends.size(); ++k) EXPECT_LE(ends[k].length, ends[k - 1].length);
  const auto found = [&](double u, double v) {
    for (const SilhouetteEnd& e : ends) {
      if ((e.pixel - full(u, v)).norm() <= 2 * 4) return true;  // within 4 working px
    }
    return false;
  };
  EXPECT_TRUE(found(10, 32.5)) << "left hand";
  EXPECT_TRUE(found(49.5, 8)) << "right hand";
  EXPECT_TRUE(found(35.5, 92)) << "left foot";
  EXPECT_TRUE(found(43.5, 92)) << "right foot";
  EXPECT_TRUE(found(39.5, 18)) << "head";
  // At most as many as asked, and none nearer the trunk than asked.
  EXPECT_EQ(silhouette_ends(cues, full(40, 45), 22, 2).size(), 2u);
  for (const SilhouetteEnd& e : silhouette_ends(cues, full(40, 45), 40, 6)) {
    EXPECT_GE(e.length, 40);
  }
  // A trunk pixel outside the silhouette starts from the silhouette's pixel nearest it.
  EXPECT_EQ(silhouette_ends(cues, full(60, 45), 22, 6).size(), 5u);
}

TEST(SilhouetteEnds, ACutByTheImagesEdgeIsNoLimbEnd) {
  // The legs run into the crop's bottom row: the feet are cut off, only hands and head remain.
  const FrameCues cues = stick_figure(99);
  const std::vector<SilhouetteEnd> ends = silhouette_ends(cues, full(40, 45), 22, 6);
  ASSERT_EQ(ends.size(), 3u);
  for (const SilhouetteEnd& e : ends) EXPECT_LT(e.pixel.y(), full(0, 90).y());
  FrameCues empty;
  empty.view = {nullptr, 0, 0, 2, 10, 10};
  empty.cls.assign(100, 0);
  EXPECT_TRUE(silhouette_ends(empty, {5, 5}, 1, 6).empty());
}

TEST(SilhouetteEnds, AnExtremityIsClaimedByTheNearestFreeLimbEnd) {
  const auto end = [](double u, double v) { return SilhouetteEnd{{u, v}, 50}; };
  // Ends: the left hand at (0, 0) explains the extremity beside it; the right hand (100, 100) is
  // lost near the trunk; the head (50, -50) explains nothing and is never moved; the foot
  // (100, 300) is free.
  const std::vector<PredictedEnd> predicted = {
      {{0, 0}, 10, true}, {{100, 100}, 10, true}, {{50, -50}, 10, false}, {{100, 300}, 10, true}};
  const std::vector<SilhouetteEnd> ends = {
      end(5, 5),      // explained by the left hand
      end(130, 20),   // the raised right hand: nearest free end is the right hand
      end(55, -48),   // the head's top: explained by the head
      end(110, 280),  // near the foot, but farther than its tolerance: the foot claims it
      end(-40, 40),   // nearer the (taken) left hand: the remaining free ends are taken too
  };
  const std::vector<int> owner = assign_ends(ends, predicted);
  EXPECT_EQ(owner, (std::vector<int>{-1, 1, -1, 3, -1}));
  // An end claims one extremity, the nearest: two extremities near the free right hand.
  const std::vector<int> two = assign_ends({end(100, 150), end(100, 130)}, predicted);
  EXPECT_EQ(two, (std::vector<int>{3, 1}));
}

}  // namespace
}  // namespace simcap::tracker::gomez
