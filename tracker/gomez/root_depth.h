// The root's distance from the camera that the silhouette's feet and top rows ask for, for the
// particle filter's depth proposals (the region and edge costs barely see a step in depth).
#pragma once

#include <optional>

#include "tracker/gomez/body_dofs.h"
#include "tracker/gomez/body_shape.h"
#include "tracker/gomez/frame_cues.h"

namespace simcap::tracker::gomez {

struct RootDepthOptions {
  double reach_m = 1.0;       // the farthest slide searched, either way
  double tolerance_px = 1.0;  // the rows must be met within this, working pixels
  // A body whose rows are off by less (working pixels) is left where it is: near the eye's
  // height the head's row moves by about a working pixel per 0.1 m of depth, and a head bobbing
  // in a step moves it as much.
  double least_px = 3.0;
};

// `x` with its root's horizontal translation moved along the ground direction of the camera ray
// through the root (the body rigidly, its image column nearly kept) to where the body's lowest
// image extent (body_extent) and its head's highest best meet the silhouette's feet row and top
// row of `cues`, in the least-squares sense. The top row counts only when the silhouette's
// topmost pixels lie over the head (not a raised hand). Nothing when the body has no
// root_tx/root_tz, no row counts, the rows are already met within `least_px`, or not met within
// the tolerance after the slide.
std::optional<State> root_depth_proposal(const BodyDofs& dofs, const BodyShape& shape,
                                         const State& x, const FrameCues& cues,
                                         const RootDepthOptions& options = {});

}  // namespace simcap::tracker::gomez
