// One frame of one person: every keypoint triangulated from the person's detections in all
// cameras, single-view left/right swaps repaired first, wrong views excluded per keypoint.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "core/camera.h"
#include "tracker/triangulate/person_association.h"
#include "tracker/triangulate/robust_point.h"
#include "tracker/triangulate/swap_repair.h"

namespace simcap::tracker {

struct PoseTriangulationOptions {
  RobustPointOptions point;
  SwapRepairOptions swaps;
  bool repair_swaps = true;
};

struct TriangulatedPose {
  std::vector<std::optional<TriangulatedPoint>> keypoints;  // in the layout's order
  std::vector<SwapFix> swaps;
};

// `views[c]`: the person's detection in camera c, or nullptr where it was not found;
// `partner[k]`: keypoint k's left/right twin (-1 none). `keypoint_count` sizes the result.
TriangulatedPose triangulate_pose(std::span<const Camera> cameras,
                                  std::span<const PersonKeypoints* const> views,
                                  std::span<const int> partner, int keypoint_count,
                                  const PoseTriangulationOptions& options = {});

}  // namespace simcap::tracker
