// Where the keypoints of a layout sit on simcap's reference humanoid (build_humanoid(), 1.75 m,
// neutral pose): the body shape the triangulation family falls back on where views are silent.
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "models/keypoint_layouts.h"

namespace simcap::tracker {

// Body points by name: the COCO-17 points (every layout's twin of them), Human3.6M's Head (the
// top of the head) and the joints humanoid_root, vc7 and skullbase.
using Anchors = std::map<std::string, Eigen::Vector3d>;
const Anchors& reference_anchors();

// The keypoint of `layout` that is `anchor`: its COCO twin or its Human3.6M truth point; -1 when
// the layout has none.
int keypoint_of(const KeypointLayout& layout, const std::string& anchor);

// Per keypoint of `layout`, its position on the reference humanoid; nullopt for keypoints that
// are no anchor (heels, toes, hands: no COCO twin).
std::vector<std::optional<Eigen::Vector3d>> reference_keypoints(const KeypointLayout& layout);

}  // namespace simcap::tracker
