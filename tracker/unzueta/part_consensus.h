// One body part's 3D centre from its 2D tracks in several cameras when some tracks have slid
// onto another limb: the camera pair whose point the most other cameras agree with (RANSAC).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "tracker/common/triangulation.h"

namespace simcap::tracker {

struct PartConsensusOptions {
  // A view agrees with a point whose projection lies within this many pixels of its track.
  double inlier_px = 12.0;
};

struct PartConsensus {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  std::vector<bool> inlier;  // per view: agrees with `position`
  int inliers = 0;
};

// Every pair of views is triangulated and scored by how many views agree with its point (the
// pair's own included), ties broken by the smaller summed error of the agreeing views; the best
// pair's agreeing views are triangulated together. nullopt with fewer than two views or when
// no pair yields a point in front of its cameras that both of them agree with.
std::optional<PartConsensus> part_consensus(const std::vector<PixelObservation>& views,
                                            const PartConsensusOptions& options = {});

}  // namespace simcap::tracker
