#include "tracker/triangulate/robust_point.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tracker/common/triangulation.h"

namespace simcap::tracker {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Fit {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  double max_error = kInfinity;
};

// The DLT over `subset` (indices into views) and its largest reprojection error there.
Fit fit(const std::vector<DltView>& dlt, std::span<const KeypointObservation> views,
        std::span<const Camera> cameras, const std::vector<int>& subset) {
  DltView chosen[32];
  int n = 0;
  for (int i : subset) chosen[n++] = dlt[i];
  const auto x = triangulate_pixel_weighted(std::span<const DltView>(chosen, n));
  if (!x) return {};
  Fit f{*x, 0.0};
  for (int i : subset) {
    const auto p = cameras[views[i].camera].project(*x);
    f.max_error = std::max(f.max_error, p ? (*p - views[i].pixel).norm() : kInfinity);
  }
  return f;
}

}  // namespace

Eigen::Matrix3d pixel_information(const Camera& camera, const Eigen::Vector3d& point) {
  const Eigen::Vector3d x = camera.to_camera(point);
  if (!(x.z() > 0)) return Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 2, 3> j;
  j << camera.K(0, 0) / x.z(), 0, -camera.K(0, 0) * x.x() / (x.z() * x.z()), 0,
      camera.K(1, 1) / x.z(), -camera.K(1, 1) * x.y() / (x.z() * x.z());
  j = j * camera.R;
  return j.transpose() * j;
}

std::vector<double> reprojection_errors(const Eigen::Vector3d& point,
                                        std::span<const KeypointObservation> views,
                                        std::span<const Camera> cameras) {
  std::vector<double> errors;
  errors.reserve(views.size());
  for (const KeypointObservation& v : views) {
    const auto p = cameras[v.camera].project(point);
    errors.push_back(p ? (*p - v.pixel).norm() : kInfinity);
  }
  return errors;
}

std::optional<TriangulatedPoint> triangulate_robust(std::span<const KeypointObservation> views,
                                                    std::span<const Camera> cameras,
                                                    const RobustPointOptions& o) {
  std::vector<DltView> dlt(views.size());
  std::vector<int> subset;
  for (size_t i = 0; i < views.size() && subset.size() < 32; ++i) {
    if (!(views[i].confidence >= o.min_confidence)) continue;
    const Camera& c = cameras[views[i].camera];
    dlt[i] = dlt_view({&c, views[i].pixel, views[i].confidence});
    subset.push_back(static_cast<int>(i));
  }
  const int min_views = std::max(2, o.min_views);
  if (static_cast<int>(subset.size()) < min_views) return std::nullopt;
  Fit best = fit(dlt, views, cameras, subset);
  int excluded = 0;
  while (best.max_error > o.max_error_px && static_cast<int>(subset.size()) > min_views) {
    Fit candidate;
    size_t drop = 0;
    for (size_t k = 0; k < subset.size(); ++k) {
      std::vector<int> rest = subset;
      rest.erase(rest.begin() + static_cast<long>(k));
      const Fit f = fit(dlt, views, cameras, rest);
      if (f.max_error < candidate.max_error) {
        candidate = f;
        drop = k;
      }
    }
    if (!std::isfinite(candidate.max_error)) break;
    subset.erase(subset.begin() + static_cast<long>(drop));
    best = candidate;
    ++excluded;
  }
  if (!(best.max_error <= o.max_error_px)) return std::nullopt;
  TriangulatedPoint p{best.position, best.max_error, 0, excluded};
  for (int i : subset) {
    if (views[i].camera < 64) p.views |= std::uint64_t{1} << views[i].camera;
    const double w = views[i].confidence * views[i].confidence;
    p.information += w * pixel_information(cameras[views[i].camera], best.position);
    if (const auto px = cameras[views[i].camera].project(best.position)) {
      p.squared_error_px2 += w * (*px - views[i].pixel).squaredNorm();
    }
  }
  return p;
}

}  // namespace simcap::tracker
