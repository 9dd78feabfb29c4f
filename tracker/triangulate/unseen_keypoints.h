// Keypoints that no two views saw in any frame (a limb behind a pillar for the whole take) have
// nothing to interpolate from; they are placed where the reference body has them instead.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "models/keypoint_layouts.h"

namespace simcap::tracker {

// frames[f][k]: keypoint k's position in frame f, nullopt where unknown; every keypoint known in
// some frame is expected to be filled over time already. Each keypoint unknown in every frame is
// placed, per frame, at its reference_keypoints() position moved by the similarity (rotation,
// translation, scale; Umeyama) that best maps the reference onto that frame's known keypoints —
// the body's pose at rest, carried by its torso and legs, so a validated track has every joint
// and the error of the guess is measured like any other. Needs three known anchor keypoints in
// the frame. Returns the keypoints placed (indices into the layout).
std::vector<int> place_unseen_keypoints(
    std::vector<std::vector<std::optional<Eigen::Vector3d>>>& frames, const KeypointLayout& layout);

}  // namespace simcap::tracker
