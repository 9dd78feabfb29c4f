// The constant-velocity Kalman filter of one image point (Unzueta 2009 eqs. 1-5, after Sánchez &
// Borro 2007): state [u v vu vv], measurement [u v]; CFOF's features, ROIs and the pelvis use it.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/video/tracking.hpp>

namespace simcap::tracker {

struct PointKalmanNoise {
  // Table 7's "process noise covariance 2 pixels" and "measurement noise covariance 1 pixel",
  // entered as the diagonals of Q and R as OpenCV's setIdentity(Q, 2) would (px^2 per frame).
  double process = 2.0;
  double measurement = 1.0;
};

class PointKalman {
 public:
  // Starts at `position` moving at `velocity` (px/frame), with the position known to the
  // measurement noise and the velocity unknown (variance `initial_velocity_variance`).
  PointKalman(cv::Point2d position, const PointKalmanNoise& noise = {},
              double initial_velocity_variance = 100.0, cv::Point2d velocity = {});

  // The a-priori state of the next frame (A x); call once per frame before correct().
  cv::Point2d predict();
  // Squared Mahalanobis distance of `measured` from the last prediction, with the innovation
  // covariance S = H P- H^T + R: the outlier test of CFOF (Alg. 2 line 9).
  double mahalanobis2(cv::Point2d measured) const;
  // The a-posteriori position after measuring `measured`.
  cv::Point2d correct(cv::Point2d measured);
  // Skips the measurement: the prediction becomes the estimate (an occluded point).
  void coast();

  // Moves the estimate by `delta` (the point was re-anchored from outside the filter).
  void translate(cv::Point2d delta);

  cv::Point2d position() const;
  cv::Point2d velocity() const;
  // The current error covariance P (4x4, CV_64F).
  const cv::Mat& covariance() const { return filter_.errorCovPost; }

 private:
  cv::KalmanFilter filter_;
};

}  // namespace simcap::tracker
