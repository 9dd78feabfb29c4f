#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "core/error.h"
#include "tracker/background_model.h"
#include "tracker/silhouettes.h"

namespace simcap::tracker {
namespace {

cv::Mat plate(cv::RNG& rng, int rows, int cols) {
  cv::Mat p(rows, cols, CV_8UC3);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      p.at<cv::Vec3b>(r, c) = cv::Vec3b(100 + (r + 2 * c) % 60, 140 - r % 30, 90 + c % 40);
  cv::Mat noise(rows, cols, CV_8UC3);
  rng.fill(noise, cv::RNG::NORMAL, 0, 2);
  return p + noise;
}

TEST(GaussianBackground, FindsTheForegroundAndIgnoresShadows) {
  cv::RNG rng(1);
  const int rows = 120, cols = 160;
  std::vector<cv::Mat> plates;
  for (int i = 0; i < 3; ++i) plates.push_back(plate(rng, rows, cols));
  const GaussianBackground model(plates);
  cv::Mat frame = plate(rng, rows, cols);
  cv::Mat truth(rows, cols, CV_8UC1, cv::Scalar(0));
  // A person-coloured block, and beside it a cast shadow: the background at 60% brightness.
  cv::rectangle(frame, cv::Rect(40, 20, 30, 70), cv::Scalar(40, 60, 170), cv::FILLED);
  cv::rectangle(truth, cv::Rect(40, 20, 30, 70), cv::Scalar(255), cv::FILLED);
  cv::Mat shadow = frame(cv::Rect(75, 60, 50, 30));
  shadow.convertTo(shadow, -1, 0.6);
  const cv::Mat fg = model.foreground(frame);
  EXPECT_GT(silhouette_iou(fg, truth), 0.97);

  BackgroundOptions no_shadows;
  no_shadows.suppress_shadows = false;
  const cv::Mat with_shadow = GaussianBackground(plates, no_shadows).foreground(frame);
  EXPECT_LT(silhouette_iou(with_shadow, truth), 0.7);  // the shadow is taken for the person
}

TEST(GaussianBackground, RejectsMismatchedImages) {
  EXPECT_THROW(GaussianBackground(std::vector<cv::Mat>{}), Error);
  const cv::Mat p(10, 10, CV_8UC3, cv::Scalar(1, 2, 3));
  const GaussianBackground model(std::vector<cv::Mat>{p});
  EXPECT_THROW(model.foreground(cv::Mat(5, 5, CV_8UC3, cv::Scalar(0))), Error);
  EXPECT_THROW(GaussianBackground(std::vector<cv::Mat>{p, cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))}),
               Error);
}

TEST(Silhouettes, IouAndMethodNames) {
  cv::Mat a(10, 10, CV_8UC1, cv::Scalar(0)), b(10, 10, CV_8UC1, cv::Scalar(0));
  EXPECT_DOUBLE_EQ(silhouette_iou(a, b), 1.0);
  a(cv::Rect(0, 0, 4, 5)).setTo(255);
  b(cv::Rect(2, 0, 4, 5)).setTo(7);
  EXPECT_DOUBLE_EQ(silhouette_iou(a, b), 10.0 / 30.0);
  EXPECT_EQ(parse_silhouette_method("mog2"), SilhouetteMethod::mog2);
  EXPECT_THROW(parse_silhouette_method("magic"), Error);
}

}  // namespace
}  // namespace simcap::tracker
