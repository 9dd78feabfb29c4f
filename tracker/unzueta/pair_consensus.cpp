#include "tracker/unzueta/pair_consensus.h"

#include <limits>

namespace simcap::tracker {
namespace {

double distance_px(const Camera& camera, const Eigen::Vector3d& x, const Eigen::Vector2d& px) {
  const auto p = camera.project(x);
  return p ? (*p - px).norm() : std::numeric_limits<double>::infinity();
}

// Whether every camera of `views` sees `a` and `b` within `px` of each other.
bool indistinct(const std::vector<PixelObservation>& views, const Eigen::Vector3d& a,
                const Eigen::Vector3d& b, double px) {
  for (const PixelObservation& v : views) {
    const auto pb = v.camera->project(b);
    if (!pb || distance_px(*v.camera, a, *pb) > px) return false;
  }
  return true;
}

// The consensus of the views farther than the inlier distance from both points' projections,
// its inlier flags indexing all of `views`.
std::optional<PartConsensus> away_from(const std::vector<PixelObservation>& views,
                                       const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                       const PartConsensusOptions& options) {
  std::vector<PixelObservation> away;
  std::vector<size_t> index;
  for (size_t i = 0; i < views.size(); ++i) {
    if (distance_px(*views[i].camera, a, views[i].pixel) <= options.inlier_px ||
        distance_px(*views[i].camera, b, views[i].pixel) <= options.inlier_px) {
      continue;
    }
    away.push_back(views[i]);
    index.push_back(i);
  }
  auto c = part_consensus(away, options);
  if (!c) return c;
  std::vector<bool> inlier(views.size(), false);
  for (size_t k = 0; k < index.size(); ++k) inlier[index[k]] = c->inlier[k];
  c->inlier = std::move(inlier);
  return c;
}

}  // namespace

PairConsensus pair_consensus(const std::vector<PixelObservation>& left,
                             const std::vector<PixelObservation>& right,
                             const PartConsensusOptions& options) {
  PairConsensus out{part_consensus(left, options), part_consensus(right, options)};
  if (!out.left || !out.right) return out;
  const Eigen::Vector3d a = out.left->position, b = out.right->position;
  if (!indistinct(left, a, b, options.inlier_px) || !indistinct(right, a, b, options.inlier_px)) {
    return out;
  }
  if (auto l = away_from(left, a, b, options)) out.left = std::move(l);
  if (auto r = away_from(right, a, b, options)) out.right = std::move(r);
  return out;
}

bool slid_onto_other(const Camera& camera, const Eigen::Vector2d& px, const Eigen::Vector3d& other,
                     const Eigen::Vector3d& previous, double inlier_px) {
  const auto o = camera.project(other), then = camera.project(previous);
  return o && then && (*o - px).norm() <= inlier_px && (*o - *then).norm() > 2 * inlier_px;
}

}  // namespace simcap::tracker
