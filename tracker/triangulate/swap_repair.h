// Left/right swaps of single views: a detector that labels a person's left knee "right" in one
// camera (and the right one "left") is caught because the swapped labels triangulate better.
#pragma once

#include <span>
#include <vector>

#include "core/camera.h"
#include "tracker/triangulate/keypoint_observation.h"

namespace simcap::tracker {

struct SwapRepairOptions {
  // A pair is examined only when one of its keypoints reprojects worse than this (pixels) in
  // some view of its all-views DLT: agreeing views cost nothing.
  double min_error_px = 6.0;
  // A view's labels are exchanged when that lowers the pair's summed RMS reprojection error to
  // less than this fraction of what it was.
  double gain = 0.5;
};

struct SwapFix {
  int keypoint = 0;  // the left (lower-index) keypoint of the pair
  int camera = 0;
};

// Examines every pair {k, partner[k]} (partner[k] < 0: none) whose two keypoints three or more
// views saw, and exchanges in place the two keypoints' observations from the view whose exchange
// helps most, repeatedly, while that helps clearly (so a pair swapped in two views of five is
// fixed too). Returns the exchanges.
std::vector<SwapFix> repair_swaps(std::vector<KeypointViews>& keypoints,
                                  std::span<const int> partner, std::span<const Camera> cameras,
                                  const SwapRepairOptions& options = {});

}  // namespace simcap::tracker
