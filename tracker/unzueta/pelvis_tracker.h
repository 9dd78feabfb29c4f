// The pelvis in the image from the silhouette (Unzueta 2009 §3.2, Alg. 6): the mean of the
// foreground pixels near the median column, sampled on a grid and smoothed by a Kalman filter.
#pragma once

#include <opencv2/core.hpp>
#include <optional>

#include "tracker/unzueta/point_kalman.h"

namespace simcap::tracker {

struct PelvisParams {
  int grid = 4;             // px between processed pixels (the thesis' 4 px at 320x240)
  double max_dist = 15.0;   // px either side of the median column (not given in the thesis)
  PointKalmanNoise kalman;  // as CFOF's
  // These parameters for a person `person_px` tall (170 px: the thesis' scale).
  PelvisParams scaled_for(double person_px) const;
};

class PelvisTracker {
 public:
  explicit PelvisTracker(const PelvisParams& params = {}) : params_(params) {}

  // Alg. 6 on `mask` (CV_8UC1, nonzero = person). The first call starts the filter; later frames
  // with no pixel in the band are predicted. Returns the filtered position; nullopt only while
  // no mask has had a pixel yet.
  std::optional<cv::Point2d> track(const cv::Mat& mask);
  // The raw measurement of Alg. 6 lines 2-21 (no filter); nullopt without pixels.
  std::optional<cv::Point2d> measure(const cv::Mat& mask) const;
  // true when the last track() measured instead of predicting.
  bool measured() const { return measured_; }

 private:
  PelvisParams params_;
  std::optional<PointKalman> filter_;
  bool measured_ = false;
};

}  // namespace simcap::tracker
