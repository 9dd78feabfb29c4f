// Fits the body's capsules to one frame whose pose is known (the first frame with --init gt or
// the first fit with --init auto): each one's radii and where its axis runs across its stick.
#pragma once

#include <vector>

#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/silhouette_view.h"

namespace simcap::tracker {

struct SurfaceFitOptions {
  int iterations = 20;
  // How far the fit may take a radius or an axis end from the typical surface before that costs
  // as much as a silhouette ray missing by a centimetre: the views of one frame leave parts of
  // some capsules unseen (a thigh's inner side, a hand against the hip).
  double radius_prior_m = 0.02;
  double offset_prior_m = 0.03;
  double min_radius_m = 0.01;
  double ray_max_miss_m = 0.3;  // rays missing every capsule by more count at this miss
  // The rays' misses are first a soft minimum over the capsules at this softness, halved every
  // iteration down to the hard minimum: early on, a ray that the capsule nearest to it cannot
  // reach (an arm, held in place by its own outline) pulls the next nearest too.
  double initial_softness_m = 0.03;
  double rim_step_m = 0.02;
};

// Left and right capsules keep one shape (mirrored): a body's sides are alike, and one side is
// often hidden where the other is seen. Minimizes, over the radii at both ends of each capsule
// and the offsets of both ends across its axis: every silhouette ray passes inside some capsule,
// every capsule's outline lies inside every silhouette, and the change from `start`.
BodySurface fit_surface(const StickModel& model, const StickPose& pose, const BodySurface& start,
                        const std::vector<SilhouetteRay>& rays,
                        const std::vector<SilhouetteView>& views,
                        const SurfaceFitOptions& options = {});

}  // namespace simcap::tracker
