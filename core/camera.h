// A calibrated pinhole camera with Brown–Conrady distortion in OpenCV's conventions.
// The renderer casts its rays and every tracker projects its points through this one class.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>

namespace simcap {

// Distortion coefficients in OpenCV's order (k1, k2, p1, p2, k3).
using Distortion = Eigen::Matrix<double, 5, 1>;

struct Camera {
  std::string name;
  int width = 0;
  int height = 0;
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();  // [fx 0 cx; 0 fy cy; 0 0 1], no skew
  Distortion dist = Distortion::Zero();
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();  // world -> camera rotation
  Eigen::Vector3d t = Eigen::Vector3d::Zero();      // X_c = R X_w + t

  // Camera at `eye` looking at `target`, image x to the right and y down, `up` (world) pointing
  // up in the image. Focal length from the horizontal field of view; principal point at centre.
  static Camera look_at(std::string name, int width, int height, double hfov_rad,
                        const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                        const Eigen::Vector3d& up = Eigen::Vector3d::UnitY());

  Eigen::Vector3d to_camera(const Eigen::Vector3d& world) const { return R * world + t; }
  Eigen::Vector3d to_world(const Eigen::Vector3d& cam) const { return R.transpose() * (cam - t); }
  Eigen::Vector3d centre() const { return -R.transpose() * t; }

  // Normalized image coordinates (z = 1) -> distorted normalized coordinates.
  Eigen::Vector2d distort(const Eigen::Vector2d& xy) const;
  // Inverse of distort() by Newton iteration; converges to ~1e-12 for realistic lenses.
  Eigen::Vector2d undistort(const Eigen::Vector2d& xy_distorted) const;

  // Pixel of a point in camera coordinates (z > 0 assumed), as cv::projectPoints computes it.
  Eigen::Vector2d project_camera(const Eigen::Vector3d& cam) const;
  // Pixel of a world point; empty when the point is not in front of the camera.
  std::optional<Eigen::Vector2d> project(const Eigen::Vector3d& world) const;

  // Unit ray direction in camera coordinates through pixel (u, v), distortion removed.
  Eigen::Vector3d unproject_camera(const Eigen::Vector2d& pixel) const;
  // Unit ray direction in world coordinates; the ray starts at centre().
  Eigen::Vector3d unproject(const Eigen::Vector2d& pixel) const;

  // True when the world point is in front of the camera and projects inside the image, with
  // `margin_px` pixels of slack on every side (pixel centres are integers, so the image spans
  // [-0.5, width - 0.5] x [-0.5, height - 0.5]).
  bool in_frustum(const Eigen::Vector3d& world, double margin_px = 0.0) const;

  // Horizontal field of view of the undistorted pinhole.
  double hfov() const;
};

}  // namespace simcap
