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
  // With silhouettes that show everyone (background subtraction), a kept pixel is someone
  // else's when the last body (widened by own_margin_m) does not project onto it and the volume
  // the gate dropped does: the ray passes the person and meets the others. Such a pixel moves to
  // the cover (it may hide the person but casts no ray), so that the others' outline next to the
  // person does not pull the limbs towards them. Off for ground-truth silhouettes, which hold
  // the person's own pixels only.
  bool others_to_cover = false;
  double own_margin_m = 0.05;
  // Inside that widened outline the pixels onto which the others' volume projects are theirs
  // too when they lie outside the body's outline widened by only core_margin_m (the body
  // explains them by the slack left for its motion alone, the others' volume directly: where
  // someone stands just behind the person, their pixels border its outline), or when that
  // volume lies more than front_m nearer the camera than the body (someone passing in front:
  // ground-truth silhouettes make those pixels cover too).
  double core_margin_m = 0.025;
  double front_m = 0.10;
};

// What the gate kept.
struct GateResult {
  bool changed = false;  // false: every voxel was kept, the silhouettes are untouched
  int components = 0;    // connected components of the hull (26-neighbourhood)
  int kept_voxels = 0;
  int dropped_voxels = 0;
  int covered_pixels = 0;  // kept pixels moved to the cover (GateOptions::others_to_cover)
  // With others_to_cover, the centres of the voxels given to the others: where they are, for
  // the next frame's restrict().
  std::vector<Eigen::Vector3d> others;
};

class PersonGate {
 public:
  PersonGate(std::vector<Camera> cameras, const GateOptions& options);
  // Keeps, of `hull` (carved from `silhouettes`), the components touching `body`, each cut to
  // reach_m of it when shared; when none touches, the nearest one. When that drops any voxel,
  // each silhouette keeps only its pixels under the projection of a kept voxel and within
  // margin_m of the body's projection, and so does each `cover` mask (when given and not
  // empty). With others_to_cover, the kept pixels the dropped volume explains better than the
  // body, or hides it at, go to `cover` (created when empty), but for those in `distinct` (per
  // camera, when given and not empty: pixels whose colour says they are the person's), and a voxel
  // beyond own_margin_m of the body that lies nearer to `others_before` (the previous frame's
  // GateResult::others) than to the body is the others'. Thread-safe.
  GateResult restrict(const Occupancy& hull, const PlacedSurface& body,
                      std::vector<cv::Mat>& silhouettes, std::vector<cv::Mat>* cover,
                      const std::vector<cv::Mat>* distinct = nullptr,
                      const std::vector<Eigen::Vector3d>* others_before = nullptr) const;

 private:
  std::vector<Camera> cameras_;
  GateOptions options_;
};

}  // namespace simcap::tracker
