// mask_box against OpenCV's boundingRect on random masks of awkward widths.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "tracker/common/mask_box.h"

namespace simcap::tracker {
namespace {

TEST(MaskBox, MatchesBoundingRect) {
  std::mt19937 rng(9);
  for (int trial = 0; trial < 300; ++trial) {
    const int cols = 1 + static_cast<int>(rng() % 70), rows = 1 + static_cast<int>(rng() % 40);
    cv::Mat mask = cv::Mat::zeros(rows, cols, CV_8UC1);
    const int set = static_cast<int>(rng() % 4);  // none, one pixel, a few, a blob
    for (int i = 0; i < (set == 0 ? 0 : set == 1 ? 1 : set == 2 ? 5 : 40); ++i) {
      mask.at<std::uint8_t>(static_cast<int>(rng() % rows), static_cast<int>(rng() % cols)) =
          static_cast<std::uint8_t>(1 + rng() % 255);
    }
    EXPECT_EQ(mask_box(mask), cv::boundingRect(mask)) << cols << "x" << rows << " set " << set;
  }
  // A view into a larger image (rows not contiguous).
  cv::Mat big = cv::Mat::zeros(50, 50, CV_8UC1);
  big.at<std::uint8_t>(12, 37) = 255;
  big.at<std::uint8_t>(30, 15) = 1;
  const cv::Mat roi = big(cv::Rect(10, 10, 33, 30));
  EXPECT_EQ(mask_box(roi), cv::Rect(5, 2, 23, 19));
}

}  // namespace
}  // namespace simcap::tracker
