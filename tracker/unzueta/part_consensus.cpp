#include "tracker/unzueta/part_consensus.h"

#include <limits>

namespace simcap::tracker {
namespace {

double error_px(const PixelObservation& v, const Eigen::Vector3d& x) {
  const auto p = v.camera->project(x);
  return p && v.camera->to_camera(x).z() > 0 ? (*p - v.pixel).norm()
                                             : std::numeric_limits<double>::infinity();
}

// The views that agree with `x`, their number and summed error.
PartConsensus score(const std::vector<PixelObservation>& views, const Eigen::Vector3d& x,
                    double inlier_px, double& summed) {
  PartConsensus c;
  c.position = x;
  c.inlier.assign(views.size(), false);
  summed = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    const double e = error_px(views[i], x);
    if (e > inlier_px) continue;
    c.inlier[i] = true;
    ++c.inliers;
    summed += e;
  }
  return c;
}

}  // namespace

std::optional<PartConsensus> part_consensus(const std::vector<PixelObservation>& views,
                                            const PartConsensusOptions& options) {
  std::optional<PartConsensus> best;
  double best_sum = 0;
  for (size_t i = 0; i < views.size(); ++i) {
    for (size_t j = i + 1; j < views.size(); ++j) {
      const auto x = triangulate(std::vector<PixelObservation>{views[i], views[j]});
      if (!x) continue;
      double sum = 0;
      PartConsensus c = score(views, *x, options.inlier_px, sum);
      if (!c.inlier[i] || !c.inlier[j]) continue;
      if (!best || c.inliers > best->inliers || (c.inliers == best->inliers && sum < best_sum)) {
        best = std::move(c);
        best_sum = sum;
      }
    }
  }
  if (!best || best->inliers <= 2) return best;
  std::vector<PixelObservation> agreeing;
  for (size_t i = 0; i < views.size(); ++i) {
    if (best->inlier[i]) agreeing.push_back(views[i]);
  }
  const auto x = triangulate(agreeing);
  if (!x) return best;
  double sum = 0;
  PartConsensus refined = score(views, *x, options.inlier_px, sum);
  // The joint fit may push a marginal view out; it stands only if it keeps the support.
  return refined.inliers >= best->inliers ? refined : best;
}

}  // namespace simcap::tracker
