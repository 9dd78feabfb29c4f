// COCO's keypoint metrics: object keypoint similarity (OKS) and the OKS-based average precision
// and recall, computed as pycocotools' COCOeval (iouType "keypoints", area range "all").
#pragma once

#include <array>
#include <optional>

#include "models/detections.h"
#include "validate/keypoint_truth.h"

namespace simcap {

// OKS of a detection against one actor's truth (pycocotools computeOks): over the keypoints k
// with a COCO sigma and a labelled truth (known and not out_of_frame: COCO's v > 0),
// mean of exp(-d_k^2 / (2 s^2 (2 sigma_k)^2)), d_k the pixel distance (whatever the detection's
// keypoint score; an undetected keypoint sits at its 0, 0), s^2 the truth's area. Empty when
// the truth has no such keypoint (COCO ignores that annotation).
std::optional<double> keypoint_oks(const ActorView& truth, const DetectedPerson& detection,
                                   const KeypointLayout& layout);

struct CocoKeypointAp {
  static constexpr int kThresholds = 10;  // OKS 0.50, 0.55, ..., 0.95
  std::array<double, kThresholds> ap_at{}, recall_at{};
  double ap = 0, ap50 = 0, ap75 = 0, ar = 0;
  int truths = 0;      // actors with a labelled keypoint (not ignored)
  int detections = 0;  // people scored (at most 20 per image, the best scored)
};

// Over every image (frame, camera) and every actor: per image the detections by descending
// score (at most 20) are matched greedily to the unmatched truth of highest OKS >= t; over all
// images the detections by descending score give precision and recall; precision is made
// non-increasing and sampled at recall 0, 0.01, .., 1; AP at t is its mean; AP the mean over
// t = 0.50:0.05:0.95, AR the mean of the final recalls.
CocoKeypointAp coco_keypoint_ap(const KeypointTruth& truth, const Detections& detections);

}  // namespace simcap
