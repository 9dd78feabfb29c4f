// One keypoint's track smoothed by a constant-velocity Kalman filter and Rauch–Tung–Striebel
// smoother whose measurement noise is each frame's triangulation covariance and whose process
// noise is chosen by maximum likelihood over the take: fast limbs keep their speed, slow ones
// are smoothed harder, with no cut-off to pick.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace simcap::tracker {

struct PointMeasurement {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  // m², positive definite
};

struct SmoothedPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // the smoother's posterior, m²
};

struct SmoothedTrack {
  std::vector<SmoothedPoint> points;  // one per frame, frames without a measurement included
  double acceleration_psd = 0;        // q, m²/s³: white acceleration's power spectral density
  double log_likelihood = 0;          // of the measurements (the innovations), up to a constant
};

// The state is position and velocity; between frames `dt` apart the velocity takes a white
// acceleration of density q (Q = q [dt³/3 I, dt²/2 I; dt²/2 I, dt I], Bar-Shalom §6.2.2). The
// first measurement starts it with an uninformative velocity. Frames without a measurement
// (nullopt) are predicted and smoothed through. Empty points when no frame has a measurement.
SmoothedTrack rts_smooth(const std::vector<std::optional<PointMeasurement>>& measurements,
                         double dt, double acceleration_psd);

// rts_smooth with q maximizing the measurements' likelihood over a log grid from 1e-3 to 1e4
// m²/s³ (factor 2 apart), refined by golden-section search on log q around the best.
SmoothedTrack rts_smooth_ml(const std::vector<std::optional<PointMeasurement>>& measurements,
                            double dt);

}  // namespace simcap::tracker
