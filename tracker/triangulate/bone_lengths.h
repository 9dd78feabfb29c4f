// Bones a take cannot stretch (thigh, shank, upper arm, forearm, pelvis): their lengths measured
// robustly over the whole take, and each frame's triangulated keypoints moved onto them.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "models/keypoint_layouts.h"

namespace simcap::tracker {

struct Bone {
  int a = -1, b = -1;  // keypoint indices of the layout
  double length = 0;   // metres; NaN while unknown
};

// The keypoint pairs of `layout` that one rigid H-Anim segment carries (simcap's humanoid,
// build_humanoid()): a joint centre and its parent's (knee–hip, elbow–shoulder, ...), or two
// children of one parent (the hips on the sacrum). Shoulders are not a pair: the clavicles move.
// Lengths are NaN.
std::vector<Bone> rigid_bones(const KeypointLayout& layout);

// Sets each bone's length to the median over frames of its keypoints' distance (frames where
// either is missing do not count; NaN when none has both). The median ignores the frames a
// wrong view or swap spoiled.
void measure_bone_lengths(std::vector<Bone>& bones,
                          const std::vector<std::vector<std::optional<Eigen::Vector3d>>>& frames);

// Moves one frame's keypoints the least, in the metric of their triangulation information
// (robust_point.h: a point moves mostly along the direction its views pin down worst), so that
// every bone with a known length and both keypoints present has exactly that length: Gauss-Newton
// steps on the linearized constraints (sequential quadratic programming) until they hold to
// 1e-9 m. Keypoints in no bone, missing ones and those whose information is singular stay where
// they are, as do the bones touching the latter.
void project_onto_bones(std::vector<std::optional<Eigen::Vector3d>>& keypoints,
                        const std::vector<Eigen::Matrix3d>& information,
                        const std::vector<Bone>& bones);

}  // namespace simcap::tracker
