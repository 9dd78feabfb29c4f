#include "tracker/moschini/icp_targets.h"

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

}  // namespace simcap::tracker
