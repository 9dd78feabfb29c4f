// mask_boxes against OpenCV's boundingRect and countNonZero of each actor's pixels, on random
// masks of awkward widths (the background is skipped eight pixels at a time).
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <random>

#include "sim/mask_boxes.h"

namespace simcap {
namespace {

TEST(MaskBoxes, MatchOpenCvPerActor) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 300; ++trial) {
    const int cols = 1 + static_cast<int>(rng() % 70), rows = 1 + static_cast<int>(rng() % 30);
    const int actors = 1 + static_cast<int>(rng() % 3);
    cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8UC1);
    const int count = static_cast<int>(rng() % 4) * 7;
    for (int i = 0; i < count; ++i) {
      const int actor = static_cast<int>(rng() % actors);
      mask.at<std::uint8_t>(static_cast<int>(rng() % rows), static_cast<int>(rng() % cols)) =
          static_cast<std::uint8_t>(actors == 1 ? 255 : actor + 1);
    }
    const std::vector<MaskBox> boxes = mask_boxes(mask, actors);
    ASSERT_EQ(static_cast<int>(boxes.size()), actors);
    for (int a = 0; a < actors; ++a) {
      const cv::Mat own = mask == (actors == 1 ? 255 : a + 1);
      EXPECT_EQ(boxes[a].pixels, cv::countNonZero(own)) << trial;
      if (boxes[a].empty()) continue;
      const cv::Rect r = cv::boundingRect(own);
      EXPECT_EQ(cv::Rect(boxes[a].x0, boxes[a].y0, boxes[a].x1 - boxes[a].x0 + 1,
                         boxes[a].y1 - boxes[a].y0 + 1),
                r)
          << trial;
    }
  }
}

}  // namespace
}  // namespace simcap
