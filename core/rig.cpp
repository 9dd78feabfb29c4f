#include "core/rig.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.h"

namespace simcap {

std::string camera_name(int index) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "cam%02d", index);
  return buf;
}

std::vector<Camera> ring_rig(int count, const Eigen::Vector3d& target, double radius, double height,
                             const ImageSpec& image) {
  if (count < 1) throw Error("ring rig: the camera count must be at least 1");
  if (radius <= 0) throw Error("ring rig: the radius must be positive");
  std::vector<Camera> cams;
  for (int i = 0; i < count; ++i) {
    const double a = 2 * std::numbers::pi * i / count;
    const Eigen::Vector3d eye(target.x() + radius * std::sin(a), height,
                              target.z() + radius * std::cos(a));
    cams.push_back(
        Camera::look_at(camera_name(i), image.width, image.height, image.hfov_rad, eye, target));
  }
  return cams;
}

std::vector<Camera> corner_rig(double size_x, double size_z, double height, double inset,
                               const Eigen::Vector3d& target, const ImageSpec& image) {
  if (size_x <= 2 * inset || size_z <= 2 * inset) {
    throw Error("corner rig: the room must be larger than twice the inset");
  }
  const double hx = 0.5 * size_x - inset, hz = 0.5 * size_z - inset;
  const Eigen::Vector3d corners[4] = {
      {hx, height, hz}, {-hx, height, hz}, {-hx, height, -hz}, {hx, height, -hz}};
  std::vector<Camera> cams;
  for (int i = 0; i < 4; ++i) {
    cams.push_back(Camera::look_at(camera_name(i), image.width, image.height, image.hfov_rad,
                                   corners[i], target));
  }
  return cams;
}

}  // namespace simcap
