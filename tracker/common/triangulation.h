// A point seen by several calibrated cameras: the linear (DLT) triangulation of Hartley &
// Zisserman §12.2 on distortion-free normalized coordinates, each view's rows weighted.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker {

struct PixelObservation {
  const Camera* camera = nullptr;
  Eigen::Vector2d pixel;
  // Scales the view's two DLT rows (a detector's confidence; Pose2Sim weights them so).
  double weight = 1.0;
};

// A view as the DLT uses it: the pixel with the lens distortion removed, in normalized image
// coordinates (z = 1). Undistorting once lets robust fits solve many subsets cheaply.
struct DltView {
  const Camera* camera = nullptr;
  Eigen::Vector2d normalized;
  double weight = 1.0;
};

DltView dlt_view(const PixelObservation& observation);

// The world point whose projections best fit `views` in the weighted algebraic (DLT) sense:
// the eigenvector of AᵀA with the smallest eigenvalue, A holding two rows per view. nullopt
// with fewer than two views or when the rays are parallel (the point would be at infinity)
// or it lies behind a camera.
std::optional<Eigen::Vector3d> triangulate(std::span<const DltView> views);
// The DLT solved again with each view's rows scaled by its focal length over the point's depth
// in that camera, so that the algebraic residuals become pixel residuals: the plain DLT weighs
// far cameras more (a row's residual is the depth times the normalized error), this one weighs
// every camera by its pixel noise, as the maximum-likelihood point does to first order.
std::optional<Eigen::Vector3d> triangulate_pixel_weighted(std::span<const DltView> views);
// The same from pixels, each camera's lens distortion removed first.
std::optional<Eigen::Vector3d> triangulate(const std::vector<PixelObservation>& views);

// Root-mean-square reprojection error of `point` in `views`, pixels (weights ignored).
double reprojection_rms(const Eigen::Vector3d& point, const std::vector<PixelObservation>& views);

}  // namespace simcap::tracker
