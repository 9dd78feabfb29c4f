// Keeps the tracked person when the silhouettes show others too (bgsub sees everyone who
// moves): the visual hull's connected parts near the body where it was last tracked, and the
// silhouettes only where those parts project.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera.h"
#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {

struct GateOptions {
  // A hull component is the person's when one of its voxels lies this close to the last body's
  // surface (a frame's motion at 30 frames/s is a few centimetres; a fast hand's 15 cm).
  double touch_m = 0.15;
  // A component the person shares with someone else (they touch, or their cones merge into
  // phantom volume between them) is cut to the voxels this close to the last body.
  double reach_m = 0.25;
  // ...and it counts as shared when more than this fraction of it lies beyond reach_m (a single
  // person's fast limb leaves a few per cent beyond it; a second body doubles the component).
  double shared_fraction = 0.05;
  // When someone else is in view, a silhouette pixel is kept only within this distance of the
  // last body (projected): phantom volume, where one camera's cone through the person meets
  // another's through someone else, touches the person's hull and would otherwise keep the
  // other person's pixels.
  double margin_m = 0.15;
};

// What the gate kept.
struct GateResult {
  bool changed = false;  // false: every voxel was kept, the silhouettes are untouched
  int components = 0;    // connected components of the hull (26-neighbourhood)
  int kept_voxels = 0;
  int dropped_voxels = 0;
};

class PersonGate {
 public:
  PersonGate(std::vector<Camera> cameras, const GateOptions& options);
  // Keeps, of `hull` (carved from `silhouettes`), the components touching `body`, each cut to
  // reach_m of it when shared; when none touches, the nearest one. When that drops any voxel,
  // each silhouette keeps only its pixels under the projection of a kept voxel and within
  // margin_m of the body's projection, and so does each `cover` mask (when given and not
  // empty). Thread-safe.
  GateResult restrict(const Occupancy& hull, const PlacedSurface& body,
                      std::vector<cv::Mat>& silhouettes, std::vector<cv::Mat>* cover) const;

 private:
  std::vector<Camera> cameras_;
  GateOptions options_;
};

}  // namespace simcap::tracker
