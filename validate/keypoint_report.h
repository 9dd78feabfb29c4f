// `simcap validate DATASET --detections FILE` as a library call: scores a 2D keypoint
// detector's output against the dataset's truth and writes keypoints2d.json/.csv + report.html.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "models/keypoint_layouts.h"
#include "validate/keypoint_scores.h"

namespace simcap {

struct DetectionValidateOptions {
  std::optional<KeypointLayoutId> layout;  // empty: inferred from the file
  std::string actor;                       // empty: the first actor
  double min_keypoint_score = 0.0;
};

struct DetectionValidation {
  KeypointScores scores;
  std::filesystem::path json, csv, html;
};

// Reads the detections (models/detections.h) and the truth of their layout
// (validate/keypoint_truth.h), scores them and writes REPORT/keypoints2d.json (schema
// simcap-keypoints2d/1), REPORT/keypoints2d.csv and REPORT/report.html. Bad input: an Error
// before anything is written.
DetectionValidation validate_detections(const std::filesystem::path& dataset,
                                        const std::filesystem::path& detections,
                                        const std::filesystem::path& out,
                                        const DetectionValidateOptions& options);

// The scores as keypoints2d.json's content and as keypoints2d.csv's.
std::string keypoint_scores_json(const KeypointScores& s, const std::string& dataset,
                                 const std::string& detections);
std::string keypoint_scores_csv(const KeypointScores& s);
// A few lines for the terminal: AP, PCK, median error, misses and swaps by visibility.
std::string keypoint_summary_text(const KeypointScores& s);

}  // namespace simcap
