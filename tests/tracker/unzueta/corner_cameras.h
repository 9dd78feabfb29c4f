// Test support for the multiview parts: four (or n) corner cameras like studio4's, with lens
// distortion, and a world point's pixel as OpenCV projects it (cv::projectPoints).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker {

// `n` cameras on a circle at 2.5 m looking at (0, 1, 0) (4: the corners of studio4's 5 m room),
// with mild barrel distortion so that the pixels depend on the lens model.
std::vector<Camera> corner_cameras(int n = 4);

// `x`'s pixel in `c` by cv::projectPoints, independent of simcap's own projection.
Eigen::Vector2d opencv_pixel(const Camera& c, const Eigen::Vector3d& x);

}  // namespace simcap::tracker
