// Left/right swaps of one camera's tracks: a camera whose left hand (or foot) follows the right
// one and whose right follows the left, while the other cameras agree on where each one is.
#pragma once

#include <Eigen/Core>

#include "core/camera.h"

namespace simcap::tracker {

// Whether `camera`'s tracks of a left/right pair (`left_px`, `right_px`) are each other's: the
// pair's points as the other cameras triangulated them (`left`, `right`) project within
// `inlier_px` of the swapped tracks, not of the tracks as labelled (one of the two is off by
// more), and the swapped labels fit better in sum. Two ends within `inlier_px` of each other in
// this view cannot be told apart, so they are never swapped.
bool tracks_swapped(const Camera& camera, const Eigen::Vector2d& left_px,
                    const Eigen::Vector2d& right_px, const Eigen::Vector3d& left,
                    const Eigen::Vector3d& right, double inlier_px);

}  // namespace simcap::tracker
