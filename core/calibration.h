// Calibration files in the formats other tools read: OpenCV FileStorage YAML (simcap's own
// calibration/opencv.yaml) and EasyMocap's intri.yml / extri.yml pair.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "core/camera.h"

namespace simcap {

// calibration/opencv.yaml: `camera_names` (sequence), then one map per camera with
// image_width, image_height, K (3x3), dist (1x5), R (3x3), rvec (3x1 Rodrigues), t (3x1, metres).
void write_opencv_calibration(const std::filesystem::path& path, const std::vector<Camera>& cams);
std::vector<Camera> read_opencv_calibration(const std::filesystem::path& path);

// EasyMocap: intri.yml holds `names`, K_<cam>, dist_<cam>; extri.yml holds `names`,
// R_<cam> (3x1 Rodrigues), Rot_<cam> (3x3), T_<cam> (3x1). EasyMocap stores no image size, so
// cameras read back have width = height = 0.
void write_easymocap_calibration(const std::filesystem::path& intri_path,
                                 const std::filesystem::path& extri_path,
                                 const std::vector<Camera>& cams);
std::vector<Camera> read_easymocap_calibration(const std::filesystem::path& intri_path,
                                               const std::filesystem::path& extri_path);

// OpenCV's Rodrigues vector (axis times angle) of a rotation matrix, as cv::Rodrigues gives it.
Eigen::Vector3d rodrigues_of(const Eigen::Matrix3d& R);

// The camera called `name`; throws Error naming `source` and the cameras it has otherwise.
const Camera& find_camera(const std::vector<Camera>& cams, std::string_view name,
                          const std::filesystem::path& source);

}  // namespace simcap
