#include "tracker/unzueta/triangulation.h"

#include <Eigen/SVD>
#include <cmath>

namespace simcap::tracker {

std::optional<Eigen::Vector3d> triangulate(const std::vector<PixelObservation>& views) {
  if (views.size() < 2) return std::nullopt;
  Eigen::MatrixXd a(2 * views.size(), 4);
  for (size_t i = 0; i < views.size(); ++i) {
    const Camera& c = *views[i].camera;
    const Eigen::Vector3d ray = c.unproject_camera(views[i].pixel);
    const Eigen::Vector2d x = ray.head<2>() / ray.z();
    Eigen::Matrix<double, 3, 4> p;
    p << c.R, c.t;
    a.row(2 * i) = x.x() * p.row(2) - p.row(0);
    a.row(2 * i + 1) = x.y() * p.row(2) - p.row(1);
  }
  const Eigen::Vector4d h =
      Eigen::JacobiSVD<Eigen::MatrixXd>(a, Eigen::ComputeFullV).matrixV().col(3);
  if (std::abs(h.w()) < 1e-12) return std::nullopt;
  const Eigen::Vector3d point = h.head<3>() / h.w();
  for (const PixelObservation& v : views) {
    if (v.camera->to_camera(point).z() <= 0) return std::nullopt;
  }
  return point;
}

double reprojection_rms(const Eigen::Vector3d& point, const std::vector<PixelObservation>& views) {
  double sum = 0;
  for (const PixelObservation& v : views) {
    const auto p = v.camera->project(point);
    sum += p ? (*p - v.pixel).squaredNorm() : INFINITY;
  }
  return views.empty() ? 0.0 : std::sqrt(sum / views.size());
}

}  // namespace simcap::tracker
