// The image-side stages of Moschini's pipeline for one frame: silhouettes, visual hull and
// centerline points. Frames are independent here, so several can be observed at once.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tracker/common/dataset.h"
#include "tracker/common/silhouettes.h"
#include "tracker/moschini/appearance.h"
#include "tracker/moschini/articulated_icp.h"
#include "tracker/moschini/occlusion_map.h"
#include "tracker/moschini/person_gate.h"
#include "tracker/moschini/skeletonize.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {

struct PerceptionOptions {
  HullOptions hull;
  SkeletonOptions skeleton;
  SilhouetteOptions silhouettes;
  // Silhouette pixels on a grid of this many pixels become rays for the fit; 0 = none.
  int ray_stride = 4;
  bool views = true;     // nearest-silhouette-pixel maps for the fit
  bool colours = false;  // rays carry their pixel's colour (the frame's RGB image is read)
  GateOptions gate;
};

struct Observation {
  int frame = 0;
  Occupancy hull;
  std::vector<CenterlinePoint> centerline;
  std::vector<Eigen::Vector3d> points;  // centerline positions, for ICP
  std::vector<SilhouetteRay> rays;      // through silhouette pixels on the ray grid
  std::vector<SilhouetteView> views;    // per camera, when PerceptionOptions::views
  std::vector<cv::Mat> silhouettes;     // per camera, as extracted (8-bit, nonzero = person)
  // Per camera, where someone else may hide the person (the other actors' pixels of the
  // ground-truth masks; with background subtraction, the pixels in the others' colours): the
  // hull is carved and the views are built from silhouettes and cover, the rays and the
  // centerline come from the silhouettes alone. Empty when no one else is known.
  std::vector<cv::Mat> cover;
  // Per camera, the silhouette pixels in colours the person alone wears (AppearanceModel::
  // distinct; with background subtraction, others about and a learned appearance): the gate
  // leaves them to the person. Empty otherwise.
  std::vector<cv::Mat> distinct;
  // Some camera's silhouette was widened where the scene blocks its view of the person
  // (Perception::widen): there the silhouettes do not show the whole person.
  bool widened = false;
  // Per camera when any abstains (Perception::abstain_until_seen): it carves nothing and its
  // views hold the whole image.
  std::vector<bool> abstains;
  GateResult gate;                     // what isolate() kept
  std::vector<double> silhouette_iou;  // per camera vs the dataset's masks, when asked for
  double silhouettes_ms = 0, hull_ms = 0, centerline_ms = 0;
};

class Perception {
 public:
  Perception(const Dataset& dataset, SilhouetteMethod method, const PerceptionOptions& options);
  // Thread-safe. With `compare_masks`, also scores the silhouettes against camNN/mask.
  Observation observe(int frame, bool compare_masks = false) const;
  const SilhouetteExtractor& silhouettes() const { return silhouettes_; }
  // Carves the hull, finds the centerline and builds the views again from the silhouettes
  // widened where `occlusion` says a camera cannot see the person; the rays keep to the
  // silhouettes as extracted. Nothing changes when no camera is blocked near the person.
  void widen(Observation& obs, const OcclusionMap& occlusion) const;
  // Keeps the person whose body was last at `body` when the silhouettes show others too
  // (person_gate.h): silhouettes, rays, hull and centerline then hold that person alone.
  // Nothing changes when the hull holds no one else.
  // With `dropped`, each camera's silhouette pixels the gate took away (the others') go there.
  // With `others_before` (the previous frame's GateResult::others), the volume near where the
  // others were stays theirs.
  GateResult isolate(Observation& obs, const PlacedSurface& body,
                     std::vector<cv::Mat>* dropped = nullptr,
                     const std::vector<Eigen::Vector3d>* others_before = nullptr) const;
  // For --init auto with others in view and silhouettes that show everyone: the dataset's mask
  // of the person to track (Dataset::mask) points at them, as a user would point at whom to
  // track. Silhouette pixels within `reach_px` of it stay the person's; the others go to the
  // cover (someone who may hide the person). Hull, centerline and views are made again.
  void point_at_person(Observation& obs, int reach_px) const;
  // A camera in whose silhouette the whole person is hidden (behind the scene, before any
  // occluder is learned) carves the hull away; when the hull is empty, the carving cameras
  // whose silhouettes hold the fewest pixels abstain one by one (Observation::abstains) until
  // it is not, keeping at least two.
  void abstain_until_seen(Observation& obs) const;
  // The rays of `obs` from the cameras in which none of the `dropped` pixels touches what is
  // kept (there, the person's silhouette may hold someone else in front): for learning the
  // person's colours. All rays when every camera has someone touching the person.
  std::vector<SilhouetteRay> rays_apart(const Observation& obs,
                                        const std::vector<cv::Mat>& dropped) const;
  // The colours of the frame's pixels under `masks`, on the ray grid (as SilhouetteRay::colour).
  std::vector<std::array<std::uint8_t, 3>> colours_under(int frame,
                                                         const std::vector<cv::Mat>& masks) const;
  // From now on, each ray lists the parts its colour may show (needs PerceptionOptions::colours).
  void set_appearance(const AppearanceModel& appearance) { appearance_ = appearance; }

 private:
  // Moves the pixels of `silhouette` in colours the person does not wear (AppearanceModel::
  // foreign) to the returned mask; those in colours the person alone wears go to `distinct`.
  cv::Mat foreign_pixels(cv::Mat& silhouette, const cv::Mat& colour, cv::Mat& distinct) const;
  // Drops the rays whose pixel the silhouettes no longer hold.
  static void keep_rays_in_silhouettes(Observation& obs);
  // Views, hull and centerline of `silhouettes` (with obs.cover), timed into `obs`.
  void shape(const std::vector<cv::Mat>& silhouettes, Observation& obs) const;
  const Dataset* dataset_;
  PerceptionOptions options_;
  SilhouetteExtractor silhouettes_;
  VisualHull hull_;
  PersonGate gate_;
  AppearanceModel appearance_;
  // Per camera, the world direction through every pixel of the ray grid (row-major), so that
  // a frame's rays cost a lookup instead of an iterative undistortion each.
  std::vector<std::vector<Eigen::Vector3f>> ray_directions_;
};

}  // namespace simcap::tracker
