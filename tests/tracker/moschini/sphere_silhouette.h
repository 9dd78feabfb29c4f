// Test support: the silhouette of a sphere drawn analytically, to test what is carved from
// silhouettes against exact geometry.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"

namespace simcap::testing {

// A pixel is inside (255) when the ray through its centre passes within `radius` of the
// sphere's centre `c` (Camera::unproject removes distortion).
cv::Mat sphere_silhouette(const Camera& cam, const Eigen::Vector3d& c, double radius);

}  // namespace simcap::testing
