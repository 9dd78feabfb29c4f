// `simcap validate` as a library call: scores a track against a dataset's ground truth and
// writes REPORT/metrics.json, REPORT/report.html and an overlay video. The closed loop and the
// stress sweeps call it after rendering and tracking.
#pragma once

#include <filesystem>
#include <string>

#include "validate/effector_scores.h"
#include "validate/evaluation.h"

namespace simcap {

struct ValidateOptions {
  double failure_threshold_mm = 100.0;
  int overlay_frames = 3;    // frames drawn over every camera (the worst one among them)
  std::string video_camera;  // camera of the overlay video; empty: the first camera
  int video_max_frames = 300;
  bool media = true;  // false: no overlays and no video (the dataset's RGB frames are not read)
  bool quiet = false;
};

struct ValidateSummary {
  Evaluation evaluation;
  std::optional<EffectorScores> effectors;  // when the track has effectors2d.csv
  std::filesystem::path metrics_json, report_html;
  std::filesystem::path video;  // empty when no video was written
  std::string video_note;       // what the video shows, or why there is none
};

// Reads DATASET and TRACK (see validation_inputs.h; and TRACK/effectors2d.csv when there is one),
// writes the report into `out`.
ValidateSummary validate_dataset(const std::filesystem::path& dataset,
                                 const std::filesystem::path& track,
                                 const std::filesystem::path& out, const ValidateOptions& options);

// Path of a dataset's RGB image: DATASET/<camera>/rgb/<frame, 6 digits>.png.
std::filesystem::path rgb_frame_path(const std::filesystem::path& dataset,
                                     const std::string& camera, int frame);

}  // namespace simcap
