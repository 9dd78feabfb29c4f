#include "tracker/icp_targets.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace simcap::tracker {
namespace {

double median_in_place(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

ClosestStick closest_stick(const StickGeometry& g, const Eigen::Vector3d& x) {
  ClosestStick best;
  double best_d2 = std::numeric_limits<double>::infinity(), best_raw = 0;
  for (int s = 0; s < kSegmentCount; ++s) {
    const Eigen::Vector3d ab = g.line_distal[s] - g.line_proximal[s];
    const double len2 = ab.squaredNorm();
    const double raw = len2 > 0 ? (x - g.line_proximal[s]).dot(ab) / len2 : 0.0;
    const double t = std::clamp(raw, 0.0, 1.0);
    const Eigen::Vector3d q = g.line_proximal[s] + t * ab;
    const double d2 = (x - q).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best_raw = raw;
      best.segment = s;
      best.point = q;
      best.along = t;
    }
  }
  best.distance = std::sqrt(best_d2);
  const int s = best.segment;
  const bool free_tip = best_raw > 1 && (s == kHead || s == kLForearm || s == kRForearm);
  best.on_line = !free_tip;
  best.match = free_tip ? best.point
                        : Eigen::Vector3d(g.line_proximal[s] +
                                          best_raw * (g.line_distal[s] - g.line_proximal[s]));
  return best;
}

double x84_threshold(std::vector<double> distances, double k, double floor) {
  if (distances.empty()) return floor;
  const double med = median_in_place(distances);
  for (double& d : distances) d = std::abs(d - med);
  const double mad = median_in_place(distances);
  return std::max(floor, med + k * 1.4826 * mad);
}

// Alternating clamped projections: exact unless the ray starts within the segment's reach, which
// a camera's centre never does.
Eigen::Vector3d nearest_on_ray(const SilhouetteRay& ray, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d& u = ray.direction;
  const Eigen::Vector3d w = ray.origin - a;
  const double aa = ab.squaredNorm(), au = ab.dot(u), aw = ab.dot(w), uw = u.dot(w);
  const double den = aa - au * au;
  const double t_lines = den > 1e-12 ? std::clamp((aw - au * uw) / den, 0.0, 1.0) : 0.0;
  auto on_ray = [&](double t) {
    return ray.origin + std::max(0.0, (a + t * ab - ray.origin).dot(u)) * u;
  };
  const double t = std::clamp((on_ray(t_lines) - a).dot(ab) / aa, 0.0, 1.0);
  return on_ray(t);
}

}  // namespace simcap::tracker
