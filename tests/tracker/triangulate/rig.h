// Test support for the triangulation family: a ring of calibrated cameras with lens distortion
// around the origin, and exact pixels of world points in them.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker::testing {

// `n` cameras 4 m from the vertical axis at 1.6 m height, 640x480, looking at (0, 1, 0), with
// mild barrel distortion so that undistortion matters.
inline std::vector<Camera> camera_ring(int n) {
  std::vector<Camera> cams;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * 3.14159265358979 * i / n + 0.3;
    Camera c = Camera::look_at("cam0" + std::to_string(i), 640, 480, 1.0,
                               {4 * std::sin(a), 1.6, 4 * std::cos(a)}, {0, 1, 0});
    c.dist << -0.12, 0.05, 0.001, -0.0005, 0.0;
    cams.push_back(c);
  }
  return cams;
}

}  // namespace simcap::tracker::testing
