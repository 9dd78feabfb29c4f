// A point seen by several calibrated cameras: the linear (DLT) triangulation of Hartley &
// Zisserman §12.2 on distortion-free normalized coordinates, for the multiview effector mode.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker {

struct PixelObservation {
  const Camera* camera = nullptr;
  Eigen::Vector2d pixel;
};

// The world point whose projections best fit `views` in the algebraic (DLT) sense, with each
// camera's lens distortion removed first. nullopt with fewer than two views or when the rays
// are parallel (the point would be at infinity) or it lies behind a camera.
std::optional<Eigen::Vector3d> triangulate(const std::vector<PixelObservation>& views);

// Root-mean-square reprojection error of `point` in `views`, pixels.
double reprojection_rms(const Eigen::Vector3d& point, const std::vector<PixelObservation>& views);

}  // namespace simcap::tracker
