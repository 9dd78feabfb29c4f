#include "tracker/common/triangulation.h"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace simcap::tracker {

DltView dlt_view(const PixelObservation& o) {
  const Eigen::Vector3d ray = o.camera->unproject_camera(o.pixel);
  return {o.camera, ray.head<2>() / ray.z(), o.weight};
}

std::optional<Eigen::Vector3d> triangulate(std::span<const DltView> views) {
  if (views.size() < 2) return std::nullopt;
  // AᵀA accumulated row by row: a 4x4 eigenproblem whatever the number of views, with no
  // allocation (the robust fits solve it for many subsets of every joint of every frame).
  Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
  for (const DltView& v : views) {
    Eigen::Matrix<double, 3, 4> p;
    p << v.camera->R, v.camera->t;
    const Eigen::RowVector4d r0 = v.weight * (v.normalized.x() * p.row(2) - p.row(0));
    const Eigen::RowVector4d r1 = v.weight * (v.normalized.y() * p.row(2) - p.row(1));
    ata.noalias() += r0.transpose() * r0 + r1.transpose() * r1;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(ata);
  const Eigen::Vector4d h = eig.eigenvectors().col(0);
  if (std::abs(h.w()) < 1e-12) return std::nullopt;
  const Eigen::Vector3d point = h.head<3>() / h.w();
  for (const DltView& v : views) {
    if (v.camera->to_camera(point).z() <= 0) return std::nullopt;
  }
  return point;
}

std::optional<Eigen::Vector3d> triangulate_pixel_weighted(std::span<const DltView> views) {
  const auto first = triangulate(views);
  if (!first || views.size() > 64) return first;
  DltView scaled[64];
  for (size_t i = 0; i < views.size(); ++i) {
    scaled[i] = views[i];
    scaled[i].weight *= views[i].camera->K(0, 0) / views[i].camera->to_camera(*first).z();
  }
  return triangulate(std::span<const DltView>(scaled, views.size()));
}

std::optional<Eigen::Vector3d> triangulate(const std::vector<PixelObservation>& views) {
  std::vector<DltView> dlt;
  dlt.reserve(views.size());
  for (const PixelObservation& v : views) dlt.push_back(dlt_view(v));
  return triangulate(std::span<const DltView>(dlt));
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
