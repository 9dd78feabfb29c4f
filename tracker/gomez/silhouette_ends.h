// Where the limbs may end in one frame whatever their colour: the geodesic extremities of the
// silhouette seen from the trunk, and which limb of the present pose each one is for (the
// particle filter's limb-end proposals for hands and feet the colour classes cannot single out).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tracker/gomez/frame_cues.h"

namespace simcap::tracker::gomez {

struct SilhouetteEnd {
  Eigen::Vector2d pixel;  // full-resolution coordinates of its working pixel's centre
  double length = 0;      // geodesic distance from the trunk inside the silhouette, working px
};

// The extremities of the silhouette (the working pixels with a colour class) of `cues` reached
// from the full-resolution pixel `trunk` (or the silhouette's pixel nearest it) by 8-connected
// paths inside it: the farthest pixel, then repeatedly the pixel farthest from the trunk and
// every extremity found, while that distance is at least `min_length` working pixels; at most
// `max_ends`, farthest first. An extremity on the crop's border is skipped (a silhouette cut by
// the image's edge ends there, not at a limb's end); each is moved uphill in the distance from
// the trunk to a local maximum of it (the middle of a long limb leads to its end, skipped when
// it was found before).
std::vector<SilhouetteEnd> silhouette_ends(const FrameCues& cues, const Eigen::Vector2d& trunk,
                                           double min_length, int max_ends);

// A limb end of the present pose as the image sees it: where it projects, and how close an
// extremity must be for the limb to explain it (pixels). `proposable`: the limb may be moved to
// an extremity it does not explain (the head explains extremities but is not moved).
struct PredictedEnd {
  Eigen::Vector2d pixel;
  double tolerance = 0;
  bool proposable = true;
};

// For each extremity, the index of the predicted end it is given to, or -1. An extremity within
// an end's tolerance is explained (-1) and that end is taken. Every other extremity is claimed by
// the nearest end that explains none, each end claiming one extremity at most, nearest pairs
// first.
std::vector<int> assign_ends(const std::vector<SilhouetteEnd>& ends,
                             const std::vector<PredictedEnd>& predicted);

}  // namespace simcap::tracker::gomez
