#include "core/camera.h"

#include <Eigen/LU>
#include <cmath>

#include "core/error.h"

namespace simcap {

Camera Camera::look_at(std::string name, int width, int height, double hfov_rad,
                       const Eigen::Vector3d& eye, const Eigen::Vector3d& target,
                       const Eigen::Vector3d& up) {
  const Eigen::Vector3d forward = (target - eye).normalized();
  const Eigen::Vector3d right_raw = forward.cross(up);
  if (right_raw.norm() < 1e-9) {
    throw Error("camera '" + name + "': viewing direction is parallel to the up vector");
  }
  const Eigen::Vector3d right = right_raw.normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Camera cam;
  cam.name = std::move(name);
  cam.width = width;
  cam.height = height;
  cam.R.row(0) = right.transpose();
  cam.R.row(1) = down.transpose();
  cam.R.row(2) = forward.transpose();
  cam.t = -cam.R * eye;
  const double f = 0.5 * width / std::tan(0.5 * hfov_rad);
  cam.K << f, 0, 0.5 * (width - 1), 0, f, 0.5 * (height - 1), 0, 0, 1;
  return cam;
}

Eigen::Vector2d Camera::distort(const Eigen::Vector2d& xy) const {
  const double x = xy.x(), y = xy.y();
  const double k1 = dist[0], k2 = dist[1], p1 = dist[2], p2 = dist[3], k3 = dist[4];
  const double r2 = x * x + y * y;
  const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
  return {x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x),
          y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y};
}

Eigen::Vector2d Camera::undistort(const Eigen::Vector2d& target) const {
  const double k1 = dist[0], k2 = dist[1], p1 = dist[2], p2 = dist[3], k3 = dist[4];
  // Damped Newton: a full step can jump past the fold of a strong barrel polynomial onto the
  // wrong branch, so a step is halved until the residual shrinks.
  Eigen::Vector2d xy = target;
  Eigen::Vector2d residual = distort(xy) - target;
  for (int iter = 0; iter < 100 && residual.squaredNorm() > 1e-30; ++iter) {
    const double x = xy.x(), y = xy.y();
    const double r2 = x * x + y * y;
    const double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
    const double dradial = k1 + r2 * (2 * k2 + 3 * k3 * r2);  // d(radial)/d(r2)
    Eigen::Matrix2d J;
    J(0, 0) = radial + 2 * x * x * dradial + 2 * p1 * y + 6 * p2 * x;
    J(0, 1) = 2 * x * y * dradial + 2 * p1 * x + 2 * p2 * y;
    J(1, 0) = J(0, 1);
    J(1, 1) = radial + 2 * y * y * dradial + 6 * p1 * y + 2 * p2 * x;
    const Eigen::Vector2d step = J.partialPivLu().solve(residual);
    double scale = 1.0;
    for (int halving = 0; halving < 30; ++halving, scale *= 0.5) {
      const Eigen::Vector2d candidate = xy - scale * step;
      const Eigen::Vector2d r = distort(candidate) - target;
      if (r.squaredNorm() < residual.squaredNorm()) {
        xy = candidate;
        residual = r;
        break;
      }
    }
    if (scale < 1e-8) break;
  }
  return xy;
}

Eigen::Vector2d Camera::project_camera(const Eigen::Vector3d& cam) const {
  const Eigen::Vector2d d = distort(cam.head<2>() / cam.z());
  return {K(0, 0) * d.x() + K(0, 2), K(1, 1) * d.y() + K(1, 2)};
}

std::optional<Eigen::Vector2d> Camera::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector3d cam = to_camera(world);
  if (cam.z() <= 0) return std::nullopt;
  return project_camera(cam);
}

Eigen::Vector3d Camera::unproject_camera(const Eigen::Vector2d& pixel) const {
  const double yd = (pixel.y() - K(1, 2)) / K(1, 1);
  const double xd = (pixel.x() - K(0, 2)) / K(0, 0);
  const Eigen::Vector2d xy = undistort({xd, yd});
  return Eigen::Vector3d(xy.x(), xy.y(), 1.0).normalized();
}

Eigen::Vector3d Camera::unproject(const Eigen::Vector2d& pixel) const {
  return R.transpose() * unproject_camera(pixel);
}

bool Camera::in_frustum(const Eigen::Vector3d& world, double margin_px) const {
  const auto px = project(world);
  if (!px) return false;
  return px->x() >= -0.5 - margin_px && px->x() <= width - 0.5 + margin_px &&
         px->y() >= -0.5 - margin_px && px->y() <= height - 0.5 + margin_px;
}

double Camera::hfov() const {
  return 2 * std::atan(0.5 * width / K(0, 0));
}

}  // namespace simcap
