// Camera rigs: the common multi-camera layouts of motion-capture studios, built from a few
// numbers. Camera names are cam00, cam01, ... in the order returned.
#pragma once

#include <vector>

#include "core/camera.h"

namespace simcap {

struct ImageSpec {
  int width = 640;
  int height = 480;
  double hfov_rad = 1.0471975511965976;  // 60 degrees
};

// Name of the i-th camera of a rig: "cam00", "cam01", ...
std::string camera_name(int index);

// N cameras evenly spaced on a horizontal circle of `radius` at `height` around `target`
// (x, z of the circle centre taken from target), all looking at `target`. The first camera is
// on the +Z side, facing the humanoid's front.
std::vector<Camera> ring_rig(int count, const Eigen::Vector3d& target, double radius, double height,
                             const ImageSpec& image);

// Four cameras in the upper corners of a room spanning [-size_x/2, size_x/2] x [0, ...] x
// [-size_z/2, size_z/2], `inset` metres in from each wall, at `height`, looking at `target`.
std::vector<Camera> corner_rig(double size_x, double size_z, double height, double inset,
                               const Eigen::Vector3d& target, const ImageSpec& image);

}  // namespace simcap
