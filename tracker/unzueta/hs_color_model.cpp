#include "tracker/unzueta/hs_color_model.h"

#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace simcap::tracker {
namespace {

// Bins as in OpenCV's CamShift sample for hue; saturation gets as many over its wider range.
constexpr int kHueBins = 30, kSaturationBins = 32;
const float kHueRange[] = {0, 180};
const float kSaturationRange[] = {0, 256};

cv::Mat histogram(const cv::Mat& hsv, const cv::Mat& mask, int channel) {
  const int bins = channel == 0 ? kHueBins : kSaturationBins;
  const float* ranges[] = {channel == 0 ? kHueRange : kSaturationRange};
  cv::Mat hist;
  cv::calcHist(&hsv, 1, &channel, mask, hist, 1, &bins, ranges);
  cv::normalize(hist, hist, 0, 255, cv::NORM_MINMAX);
  return hist;
}

cv::Mat project(const cv::Mat& hsv, const cv::Mat& hist, int channel) {
  const float* ranges[] = {channel == 0 ? kHueRange : kSaturationRange};
  cv::Mat out;
  cv::calcBackProject(&hsv, 1, &channel, hist, out, ranges);
  return out;
}

}  // namespace

void HsColorModel::learn(const cv::Mat& hsv, cv::Rect roi, const cv::Mat& mask) {
  const cv::Rect centre(roi.x + roi.width / 4, roi.y + roi.height / 4, std::max(1, roi.width / 2),
                        std::max(1, roi.height / 2));
  const cv::Rect inside = centre & cv::Rect(0, 0, hsv.cols, hsv.rows);
  cv::Mat sub_mask = mask.empty() ? cv::Mat() : mask(inside);
  if (inside.empty() || (!mask.empty() && cv::countNonZero(sub_mask) == 0)) {
    throw Error("colour model: no pixel of the body part in the centre of its region (" +
                std::to_string(roi.width) + "x" + std::to_string(roi.height) + " at " +
                std::to_string(roi.x) + "," + std::to_string(roi.y) + ")");
  }
  const cv::Mat sub = hsv(inside);
  hue_ = histogram(sub, sub_mask, 0);
  saturation_ = histogram(sub, sub_mask, 1);
}

cv::Mat HsColorModel::back_project(const cv::Mat& hsv, cv::Rect roi, const cv::Mat& mask) const {
  const cv::Rect inside = roi & cv::Rect(0, 0, hsv.cols, hsv.rows);
  if (inside.empty()) return cv::Mat(0, 0, CV_8UC1);
  const cv::Mat sub = hsv(inside);
  cv::Mat probability = cv::min(project(sub, hue_, 0), project(sub, saturation_, 1));
  if (!mask.empty()) probability.setTo(0, mask(inside) == 0);
  return probability;
}

}  // namespace simcap::tracker
