// A left/right pair of parts (hands, feet) from their multiview tracks: two limbs are not one
// point, so when both parts' consensus lands on one place, the tracks elsewhere are asked again.
#pragma once

#include <optional>
#include <vector>

#include "tracker/unzueta/part_consensus.h"

namespace simcap::tracker {

struct PairConsensus {
  std::optional<PartConsensus> left, right;
};

// Each part's part_consensus; then, when the two points project within `inlier_px` of each
// other in every camera that sees either part (both flocks on one limb in the agreeing cameras,
// the other limb left to the minority), each part whose tracks away from that point (farther
// than `inlier_px` from both projections) agree among themselves takes their consensus instead.
// Views are matched between the two lists by their camera; inlier flags index each part's own
// `views`.
PairConsensus pair_consensus(const std::vector<PixelObservation>& left,
                             const std::vector<PixelObservation>& right,
                             const PartConsensusOptions& options = {});

// Whether a part's track at `px` in `camera` has slid onto the other part of its pair: it lies
// within `inlier_px` of the other part's point (`other`) where the part's own previous point
// (`previous`) projected more than twice that from it. (Used only where the part has no
// consensus: leaving such views out of a consensus cost the hold-out, UNZUETA.md, mv40.)
bool slid_onto_other(const Camera& camera, const Eigen::Vector2d& px, const Eigen::Vector3d& other,
                     const Eigen::Vector3d& previous, double inlier_px);

}  // namespace simcap::tracker
