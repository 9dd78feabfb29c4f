// Calibration as the TOML file of Anipose (aniposelib's CameraGroup.dump/load) and Pose2Sim
// (Calib.toml): one table per camera with OpenCV intrinsics and world->camera extrinsics.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"

namespace simcap {

// Tables [cam_0], [cam_1], ... in rig order, each with name, size = [width, height] (integers),
// matrix (3x3 K), distortions (k1, k2, p1, p2, k3), rotation (Rodrigues vector of the
// world->camera R), translation (t, metres) and fisheye = false; then [metadata] with
// adjusted = false and error = 0.0 (Pose2Sim's keys). Floats are written with a decimal point,
// so that strict TOML readers (Python's `toml`) see homogeneous arrays. The world is simcap's
// (+Y up, metres).
std::string toml_calibration(const std::vector<Camera>& cams);
// Writes toml_calibration() to `path` atomically.
void write_toml_calibration(const std::filesystem::path& path, const std::vector<Camera>& cams);

}  // namespace simcap
