// One keypoint triangulated from every camera that saw it, robust to a camera that is wrong:
// a confidence-weighted DLT, then Pose2Sim's exclusion of views while the reprojection is poor.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "core/camera.h"
#include "tracker/triangulate/keypoint_observation.h"

namespace simcap::tracker {

struct RobustPointOptions {
  // A fit whose largest reprojection error exceeds this (pixels) drops a view and refits.
  double max_error_px = 15.0;
  int min_views = 2;            // never fewer views than this (a DLT needs two)
  double min_confidence = 0.2;  // observations scored lower are not used at all
};

struct TriangulatedPoint {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double max_error_px = 0;  // largest reprojection error among the views kept
  std::uint64_t views = 0;  // bit c: camera c's observation was used (cameras 0..63)
  int excluded = 0;         // views dropped for their reprojection error
  // Fisher information of the position under unit pixel noise scaled by the confidence: the sum
  // over the views kept of JᵀJ·confidence², J the 2x3 pixel Jacobian of the (pinhole) projection.
  // Its inverse is the point's covariance in px² units: large along a lone view's ray.
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  // Σ confidence² · reprojection error² over the views kept, px²: with 2·views − 3 degrees of
  // freedom, what the pixel noise of the take is estimated from.
  double squared_error_px2 = 0;
};

// nullopt when fewer than min_views confident observations remain or when even the best
// min_views-subset reprojects worse than max_error_px (the keypoint is then missing in this
// frame, as in Pose2Sim, and filled over time). Excluding: the view whose removal leaves the
// smallest largest-error among the others goes first (leave-one-out; deterministic, and with
// one wrong camera it removes that camera even when it has pulled the joint fit towards itself).
std::optional<TriangulatedPoint> triangulate_robust(std::span<const KeypointObservation> views,
                                                    std::span<const Camera> cameras,
                                                    const RobustPointOptions& options = {});

// JᵀJ of the pixel projection of `point` in `camera` (pinhole, distortion neglected): how much
// one view pins the point down, per direction; zero behind the camera.
Eigen::Matrix3d pixel_information(const Camera& camera, const Eigen::Vector3d& point);

// Reprojection error of `point` in each view, pixels (infinite behind a camera).
std::vector<double> reprojection_errors(const Eigen::Vector3d& point,
                                        std::span<const KeypointObservation> views,
                                        std::span<const Camera> cameras);

}  // namespace simcap::tracker
