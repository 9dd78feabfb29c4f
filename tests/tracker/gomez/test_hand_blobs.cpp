// The hands' regions of a segmented frame: connected regions of one class, filtered by size and
// ordered by it, in full-resolution pixel coordinates, and their far end from a shoulder.
#include <gtest/gtest.h>

#include "tracker/gomez/hand_blobs.h"

namespace simcap::tracker::gomez {
namespace {

TEST(HandBlobs, RegionsOfTheClassLargestFirstAtFullResolution) {
  FrameCues cues;
  cues.view = {nullptr, 100, 50, 2, 40, 30};
  cues.cls.assign(40 * 30, 0);
  const auto fill = [&](int u0, int v0, int w, int h, std::uint8_t c) {
    for (int v = v0; v < v0 + h; ++v) {
      for (int u = u0; u < u0 + w; ++u) cues.cls[v * 40 + u] = c;
    }
  };
  fill(2, 3, 5, 2, 3);    // 10 pixels
  fill(20, 20, 3, 4, 3);  // 12 pixels
  fill(30, 2, 1, 2, 3);   // 2 pixels: too small
  fill(10, 10, 6, 6, 2);  // another class
  fill(23, 20, 2, 2, 2);  // touches the second region, another class
  const std::vector<HandBlob> blobs = hand_blobs(cues, 3, 3, 4);
  ASSERT_EQ(blobs.size(), 2u);
  EXPECT_EQ(blobs[0].pixels.size(), 12u);
  EXPECT_EQ(blobs[1].pixels.size(), 10u);
  // Working pixel (20, 20) covers full-resolution pixels 140-141 x 90-91: centre 140.5, 90.5.
  const Eigen::Vector2d from(0, 0);
  EXPECT_LT(
      (blobs[1].farthest_from(from) - Eigen::Vector2d(100 + 6 * 2 + 0.5, 50 + 4 * 2 + 0.5)).norm(),
      1e-9);
  EXPECT_LT((blobs[0].farthest_from(Eigen::Vector2d(140.5, 90.5)) -
             Eigen::Vector2d(100 + 22 * 2 + 0.5, 50 + 23 * 2 + 0.5))
                .norm(),
            1e-9);
  EXPECT_EQ(hand_blobs(cues, 3, 3, 1).size(), 1u);
  EXPECT_TRUE(hand_blobs(cues, 5, 1, 4).empty());
}

}  // namespace
}  // namespace simcap::tracker::gomez
