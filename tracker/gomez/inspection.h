// A picture of what the monocular tracker compares on one frame, for --inspect: the colour crop
// at working resolution, its colour classes, the model's classes in a pose with its occluding
// contour, and the edge distance map with the contour over it.
#pragma once

#include <opencv2/core/mat.hpp>

#include "tracker/gomez/colour_classes.h"
#include "tracker/gomez/frame_cues.h"
#include "tracker/gomez/pose_scorer.h"

namespace simcap::tracker::gomez {

// Four panels side by side, each the working image enlarged `zoom` times (CV_8UC3, the
// cues' channel order).
cv::Mat inspection_image(const PoseScorer& scorer, const ColourClasses& classes,
                         const FrameCues& cues, const State& x, int zoom = 3);

}  // namespace simcap::tracker::gomez
