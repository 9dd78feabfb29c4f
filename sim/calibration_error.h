// rig.calibration_error applied: the calibration a dataset writes to calibration/ when the scene
// asks for a wrong one, and the exact perturbation of each camera (meta.json records it).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/camera.h"
#include "scenes/capture_settings.h"

namespace simcap {

// How one written camera differs from the true one.
struct CameraPerturbation {
  // R_written = AngleAxis(rotation_deg, rotation_axis) * R_true: the axis is in the true
  // camera's frame, and the centre stays where it was before centre_shift_m.
  Eigen::Vector3d rotation_axis = Eigen::Vector3d::UnitZ();
  double rotation_deg = 0;
  Eigen::Vector3d centre_shift_m = Eigen::Vector3d::Zero();  // C_written = C_true + shift (world)
  double focal_scale = 1;                                    // fx and fy times this
  Eigen::Vector2d principal_shift_px = Eigen::Vector2d::Zero();  // cx, cy plus this
};

// The perturbation of the camera called `name`: every direction and sign drawn from
// (error.seed, name), the magnitudes exactly the error's.
CameraPerturbation camera_perturbation(const CalibrationError& error, const std::string& name);
Camera perturb(const Camera& camera, const CameraPerturbation& p);

// The cameras as calibration/ states them: perturbed when `error` is on, else `cameras`.
std::vector<Camera> written_calibration(const std::vector<Camera>& cameras,
                                        const CalibrationError& error);

}  // namespace simcap
