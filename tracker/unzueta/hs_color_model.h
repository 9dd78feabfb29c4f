// CFOF's chrominance model of a body part (Unzueta 2009 §3.1): hue and saturation histograms
// learned on the central subregion of its ROI, back-projected separately and combined by "&".
#pragma once

#include <opencv2/core.hpp>

namespace simcap::tracker {

class HsColorModel {
 public:
  HsColorModel() = default;
  // Learns from the pixels of `hsv` (CV_8UC3, OpenCV's HSV: H in [0, 180)) in the central half
  // (in each direction) of `roi`; with a non-empty `mask` (CV_8UC1) only where it is set. Throws
  // Error when no pixel remains.
  void learn(const cv::Mat& hsv, cv::Rect roi, const cv::Mat& mask = {});
  bool learned() const { return !hue_.empty(); }

  // Colour probability (0-255) of every pixel of `roi` (clipped to the image), CV_8UC1 of the
  // clipped ROI's size: the minimum of the hue and saturation back-projections (the thesis'
  // "&" of two probability images), zero where a non-empty `mask` is unset.
  cv::Mat back_project(const cv::Mat& hsv, cv::Rect roi, const cv::Mat& mask = {}) const;

 private:
  cv::Mat hue_, saturation_;  // 1-D histograms scaled to a maximum of 255
};

}  // namespace simcap::tracker
