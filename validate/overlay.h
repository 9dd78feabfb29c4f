// Tracked and true skeletons drawn over a camera's RGB frame: the picture that shows at a glance
// where a tracker went wrong. Points are projected with the dataset's calibrated Camera.
#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/camera.h"

namespace simcap {

// Stick-figure bones between evaluated joints (indices into `joints`): the HE15 figure (pelvis
// to hips and thorax, thorax to head and shoulders, down the limbs), and any other joint linked
// to its nearest evaluated ancestor in the canonical humanoid.
std::vector<std::pair<int, int>> stick_figure_bones(const std::vector<std::string>& joints);

// Copy of `rgb` (CV_8UC3, RGB order) with the true skeleton in green and the tracked one in red,
// and a caption in the top-left corner. Joints behind the camera are left out.
cv::Mat draw_overlay(const cv::Mat& rgb, const Camera& camera, const Eigen::Matrix3Xd& truth,
                     const Eigen::Matrix3Xd& estimate,
                     const std::vector<std::pair<int, int>>& bones, const std::string& caption);

}  // namespace simcap
