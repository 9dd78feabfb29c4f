// Unzueta's 2D tracking in one camera (thesis ch. 3): head, hands and feet by CFOF, the pelvis
// from the silhouette, and the self-occlusion rule of §3.3.1 (of two overlapping ROIs the one
// nearer the camera keeps its optical flow, the other is predicted).
#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <optional>

#include "tracker/unzueta/cfof.h"
#include "tracker/unzueta/effectors.h"
#include "tracker/unzueta/initial_regions.h"
#include "tracker/unzueta/limb_end.h"
#include "tracker/unzueta/pelvis_tracker.h"

namespace simcap::tracker {

struct CameraTrackerParams {
  CfofParams cfof;      // at the thesis' scale; scaled to the person's size at initialization
  PelvisParams pelvis;  // likewise
  // Two parts overlap (§3.3.1) when their boxes (the ROIs shrunk to `part_box` of their side,
  // about the part's own size) intersect over this fraction of the smaller one.
  double part_box = 0.6;
  double overlap_fraction = 0.2;
  // CFOF's colour probability counts only inside the silhouette (simcap's addition; off is the
  // thesis, whose colour model also lights up a floor of the shoes' colour).
  bool colour_in_silhouette = true;
  // End-effector anchoring (simcap's addition): after CFOF, each part's ROI moves onto the far
  // end of its coloured blob (limb_end.h), the mean of the blob's pixels within `anchor_length`
  // (fractions of the person's height: the part's length) of its geodesically farthest pixel
  // from where the body enters the blob.
  // Rendered skin and cloth are untextured, so a flock slides along a forearm or the neck
  // towards the body; an end-effector is, by definition, where its limb ends.
  bool anchor = true;
  double anchor_color = 0.2;  // colour probability a blob pixel needs
  // The blob is searched this far (a fraction of the person's height) around the ROI's centre:
  // far enough to hold a forearm and hand, so that the sleeve is in view.
  double anchor_window = 0.3;
  // Only the body's contacts with the blob this near (a fraction of the person's height) to the
  // one nearest the limb's root count as where the limb comes in.
  double anchor_root_tolerance = 0.05;
  std::array<double, kEffectorCount - 1> anchor_length = {0.13, 0.09, 0.09, 0.06, 0.06};
  // An anchored end farther than this many part lengths (`anchor_length`) from where CFOF put
  // the part is not this part's end: two limbs of one colour touch (crossed forearms, a hand on
  // the face) and their blobs merged, whose far end belongs to the other limb.
  double anchor_gate = 1.0;
  // Parts that are not tracked (hidden, or lost) move with the pelvis' image motion
  // (CfofTracker::track's `carry`); off: they coast on their own velocity alone.
  bool carry_with_pelvis = true;
  // Re-finding a lost part (simcap's addition): a part that has not been tracked for
  // `refind_patience` frames in a row (hidden behind a nearer part, which stops its optical
  // flow for as long as it stays there, or coasted off the body, where no colour restarts it)
  // is searched for from its limb's root: the far end (limb_end.h) of the part's coloured blob
  // nearest the root within `refind_reach` (a fraction of the person's height) of it, other
  // tracked parts' ROIs masked out, restarts CFOF there (CfofTracker::restart). The reach is
  // the limb's length from the body's proportions (shoulder to fingertip 0.44 of the height:
  // upper arm 0.186, forearm 0.146, hand 0.108, Winter's table: `track --refind-reach 0.44`);
  // 0: never re-found. Off by default: it finds gest3's lost hand (MPJPE 111 -> 48 mm) but
  // costs the walk (studio4 230 -> 257 mm; UNZUETA.md).
  int refind_patience = 30;
  std::array<double, kEffectorCount - 1> refind_reach = {0, 0, 0, 0, 0};
};

class CameraTracker {
 public:
  explicit CameraTracker(const CameraTrackerParams& params = {}) : params_(params) {}

  // Starts every part with an ROI in `regions` (the others start lost where the pelvis is) on
  // the first frame (`bgr` CV_8UC3, `silhouette` CV_8UC1). Throws Error when no part can start.
  void initialize(const cv::Mat& bgr, const cv::Mat& silhouette, const InitialRegions& regions);
  // Starts with every part lost and without colours, the person `person_px` high in the image:
  // a camera that does not see the person yet (multiview), whose parts other cameras' consensus
  // brings in when they show (borrow_colours, correct).
  void start_lost(const cv::Mat& bgr, const cv::Mat& silhouette, double person_px);
  // The next frame. `depth[e]` is each part's distance from this camera (any consistent measure,
  // e.g. the previous 3D estimate's camera z) for the occlusion rule; NaN: unknown. `root[e]`
  // is where the part's limb starts in the image (the neck's base for the head, shoulders for
  // hands, hips for feet, e.g. the previous pose projected) for the anchoring; nullopt: unknown.
  void track(const cv::Mat& bgr, const cv::Mat& silhouette,
             const std::array<double, kEffectorCount>& depth,
             const std::array<std::optional<cv::Point2d>, kEffectorCount>& root = {});

  // Moves a part to `at` in the last frame, where other cameras put it (multiview: their
  // consensus point projected): a tracked or predicted part is shifted there, a lost one
  // restarts there when its colours show (CfofTracker::restart). Not for the pelvis.
  void correct(Effector e, cv::Point2d at);
  // A part that learnt no colours takes those `donor` (another camera) learnt for it, its ROI
  // `scale` times the donor's (CfofTracker::borrow_colours), so that `correct` can restart it.
  void borrow_colours(Effector e, const CameraTracker& donor, double scale);
  // Exchanges two parts' whole tracks (flock, filters, colours), e.g. a left and right hand
  // whose flocks each followed the other limb (view_swaps.h). Not for the pelvis.
  void swap(Effector a, Effector b);

  // The part's image position (the ROI centre; the pelvis from Alg. 6).
  cv::Point2d position(Effector e) const;
  CfofState state(Effector e) const;
  // Pixels on a CFOF part in the last frame: its anchored end (CameraTrackerParams::anchor), or
  // else CFOF's selected features. Not for the pelvis.
  const std::vector<cv::Point>& surface(Effector e) const;
  cv::Rect2d roi(Effector e) const;
  double person_px() const { return person_px_; }

 private:
  CfofFrame frame(const cv::Mat& bgr, const cv::Mat& silhouette) const;
  // Where the part is expected in the next frame, about its own size.
  cv::Rect2d part_box(const CfofTracker& t) const;
  // The far end of the part's coloured blob in its ROI (see CameraTrackerParams::anchor).
  std::optional<LimbEnd> far_end(Effector e, const CfofFrame& frame, const cv::Mat& silhouette,
                                 std::optional<cv::Point2d> root) const;
  // Restarts a part lost for `refind_patience` frames where its limb ends (see refind_reach).
  void refind(Effector e, const CfofFrame& frame, const cv::Mat& silhouette,
              std::optional<cv::Point2d> root);
  CameraTrackerParams params_;
  CfofParams cfof_;
  std::array<CfofTracker, kEffectorCount - 1> parts_;
  std::array<std::vector<cv::Point>, kEffectorCount - 1> surface_;
  std::array<int, kEffectorCount - 1> untracked_{};  // frames in a row not tracked
  PelvisTracker pelvis_;
  cv::Point2d pelvis_position_;
  bool pelvis_seen_ = false;
  CfofFrame previous_;
  double person_px_ = 0;
};

}  // namespace simcap::tracker
