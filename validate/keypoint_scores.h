// 2D keypoint scores of a detector against exact truth: per keypoint and visibility class the
// miss rate, pixel error, PCK and left/right swaps of the detection chosen for one actor.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "models/detections.h"
#include "validate/keypoint_ap.h"
#include "validate/keypoint_truth.h"

namespace simcap {

// PCK thresholds as fractions of the actor's torso size and of its height in each image.
inline constexpr std::array<double, 3> kTorsoFractions = {0.1, 0.2, 0.5};
inline constexpr std::array<double, 3> kHeightFractions = {0.025, 0.05, 0.1};

// Visibility classes of the scores: joints2d.csv's four labels and `unlabelled` (a truth pixel
// with no label: the Human3.6M-only points inside the image), in VisibilityLabel's order.
inline constexpr int kVisibilityClasses = 5;
std::string_view visibility_class_name(int v);

// One group of keypoint-images (a keypoint in one image of the actor).
struct KeypointGroup {
  int keypoints = 0;  // with ground truth
  int detected = 0;   // the chosen person has the keypoint with score > min_keypoint_score
  std::array<int, 3> within_torso{}, within_height{};  // detected within each PCK threshold
  std::vector<double> errors_px;                       // of the detected keypoints
  int pairs = 0;    // detected keypoints whose detected mirror partner could be checked
  int swapped = 0;  // ... that were swapped with it

  double miss_rate() const;        // 1 - detected / keypoints (NaN when empty)
  double median_px() const;        // NaN when none detected
  double mean_px() const;          // NaN when none detected
  double pck_torso(int i) const;   // within_torso[i] / keypoints (a miss is not correct)
  double pck_height(int i) const;  // within_height[i] / keypoints
  double swap_rate() const;        // swapped / pairs (NaN when no pairs)
  void add(const KeypointGroup& other);
};

struct KeypointScores {
  KeypointLayoutId layout;
  std::string actor;
  double min_keypoint_score = 0;
  // The choice of the actor's detection per image (highest OKS against its truth).
  int images = 0;                     // images where the actor has pixels
  int no_person = 0, one_person = 0;  // ... with no detected person, with one
  int several_people = 0;             // ... with several
  int several_chosen_top = 0;         // ... where the chosen one has the highest person score
  int unmatched = 0;  // images with people, none of OKS >= kMinMatchOks: the actor is missed
  // Groups: `all` pools the in-frame classes (out_of_frame is reported on its own).
  KeypointGroup all;
  std::array<KeypointGroup, kVisibilityClasses> by_visibility;
  // [keypoint][class], layout order; keypoints without ground truth stay empty.
  std::vector<std::array<KeypointGroup, kVisibilityClasses>> per_keypoint;
  int swap_pairs = 0, swapped_pairs = 0;  // mirror pairs checked / swapped, in frame
  CocoKeypointAp coco;                    // over every actor
};

// A person is the actor's only with at least this OKS against its truth: someone else, or a
// false detection far from it, is not the actor found with enormous errors.
inline constexpr double kMinMatchOks = 0.1;

struct KeypointScoreOptions {
  int actor = 0;                    // index into the truth's actors
  double min_keypoint_score = 0.0;  // a keypoint is detected when its score is above this
};

// Per image where the actor has pixels: torso size = mean of the true 2D distances left
// shoulder - right hip and right shoulder - left hip (H-Anim joint centres), body height =
// the height of the actor's mask box; the detection of highest OKS against the actor's truth is
// the actor's when that OKS is at least kMinMatchOks, else all the actor's keypoints are missed. A
// detected keypoint with partner p (both with truth, in frame, detected) is swapped when |d_k -
// t_p| + |d_p - t_k| < |d_k - t_k| + |d_p - t_p|.
KeypointScores score_keypoints(const KeypointTruth& truth, const Detections& detections,
                               const KeypointScoreOptions& options);

}  // namespace simcap
