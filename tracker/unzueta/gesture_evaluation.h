// Unzueta's gesture chapter scored on simcap's labelled corpora (gt/gestures.csv): spotting by
// kinetic pseudo-energy, recognition of the spotted dynamic gestures (normalised, K-NN or SVM)
// and of quasi-static poses (K-NN), and the per-limb labels combined frame by frame; each corpus
// (one subject) is recognised by classifiers trained on the others (leave-one-subject-out).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "core/gesture_table.h"
#include "tracker/unzueta/gesture_classifier.h"
#include "tracker/unzueta/gesture_signals.h"
#include "tracker/unzueta/gesture_spotting.h"

namespace simcap::tracker {

struct GestureCorpus {
  std::string name;  // shown in reports (the track folder)
  double fps = 30.0;
  BodySignals signals;                 // as the track has them, unsmoothed
  std::vector<GestureInterval> truth;  // one actor's rows
};

struct GestureOptions {
  // Gaussian smoothing of the signals over time, frames (gesture_signals.h smooth_signals).
  double smooth_sigma = 1.0;
  SpottingParams spotting;
  int states = 30;     // Table 12
  double size = 50.0;  // Table 12, "maximum DoF length"
  int k = 1;           // Table 15
  double match_iou =
      0.5;              // a spotted stretch finds a true gesture of its limb at this temporal IoU
  int pose_stride = 5;  // every n-th frame of a held pose trains the pose classifier
  // The path recognised is the spotted stretch widened to where the hand's speed (on the
  // smoothed path that is recognised) falls below this fraction of its peak in the stretch
  // (simcap's; 0 is the thesis, the stretch itself). 5 % of the peak speed is the usual onset and
  // offset of a reaching movement in motor-control studies. The stretch is the part of a gesture
  // above the spotting threshold, whose slow first and last strokes it cuts by an amount that
  // depends on the speed and, on a tracked hand, on its jitter at the threshold crossings: the
  // same digit is cut differently in each subject (a `1` without its slow upstroke reads as a `7`,
  // a `7` without its slow bar as a `1`).
  double path_speed_fraction = 0.05;
};

struct SpottedGesture {
  std::string limb;
  int first_frame = 0, last_frame = 0;
  std::string truth;  // label of the matched true gesture; empty for a false detection
  double iou = 0;
  int path_first = 0, path_last = 0;  // the frames of the path recognised
  // Every spotted one; "unknown" when no other corpus has a gesture of this limb.
  std::map<GestureClassifierKind, std::string> predicted;
};

struct Confusion {
  std::vector<std::string> labels;        // sorted; "limb:label"
  std::vector<std::vector<long>> counts;  // [truth][predicted]
  long total = 0, correct = 0;
  double accuracy = 0;
};

struct CorpusGestures {
  std::string name;
  std::vector<SpottedGesture> spotted;
  long truth_count = 0, matched = 0;
  long pose_frames = 0, pose_correct = 0;    // frames of held poses outside spotted gestures
  long label_frames = 0, label_correct = 0;  // frames whose true limb label the stream matches
  // Per limb (kGestureLimbs) and signal frame: the recognised dynamic gesture inside a spotted
  // stretch, else the recognised held pose (the SVM's, after K-NN, is not used here).
  std::array<std::vector<std::string>, 2> stream;
};

struct GestureResults {
  std::vector<CorpusGestures> corpora;
  long spotted = 0, truth_count = 0, matched = 0;
  double precision = 0, recall = 0, f1 = 0;
  std::map<GestureClassifierKind, Confusion> recognition;  // of the matched spotted gestures
  Confusion poses;
  double label_accuracy = 0;  // combined per-limb label stream against the truth's labels
};

// What spotting thresholds for one hand's path (`signals.hand[l]`): the psE of the path rebuilt
// from its median velocities (SpottingParams::velocity_median), smoothed by `smooth_sigma`.
std::vector<double> spotting_energy(const std::vector<Eigen::Vector3d>& hand, double fps,
                                    const GestureOptions& options);

// The signals are smoothed by `smooth_sigma` for recognition. Needs at least two corpora. Throws
// Error when a corpus' truth names a limb other than kGestureLimbs or there is nothing to train on.
GestureResults evaluate_gestures(const std::vector<GestureCorpus>& corpora,
                                 const GestureOptions& options);

}  // namespace simcap::tracker
