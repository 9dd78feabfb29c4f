// The closed loop render -> track -> validate, composed here in apps/ (the libraries do not call
// each other) and shared by `simcap loop`, `simcap demo` and `simcap stress`.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>
#include <string>

#include "apps/simcap/loop_detector.h"
#include "apps/simcap/option_groups.h"
#include "sim/render_job.h"
#include "tracker/registry.h"
#include "validate/keypoint_report.h"
#include "validate/sweep_spec.h"
#include "validate/validate_job.h"

namespace simcap::cli {

struct LoopRun {
  std::filesystem::path scene;
  RenderOptions render;
  tracker::TrackOptions track;
  ValidateOptions validate;
  bool quiet = false;
  // A 2D detector run on the rendered images (OUT/detections.json), whose keypoints the
  // triangulate tracker then lifts; none: the tracker reads the images itself.
  LoopDetector detector = LoopDetector::none;
  TruthNoise truth_noise{2.0, 1};  // --detector truth-noise
  // When set, this dataset is tracked and validated as it is and nothing is rendered (a sweep
  // renders a scene once for all the tracker settings it compares).
  std::filesystem::path existing_dataset;
};

struct LoopResult {
  std::filesystem::path scene, out, dataset;
  RenderSummary render;  // frames = 0 when the dataset was not rendered by this run
  TrackSummary track;
  ValidateSummary validate;
  LoopDetector detector = LoopDetector::none;
  // With a detector: its 2D keypoints scored against the truth (OUT/report2d).
  std::optional<DetectionValidation> keypoints2d;
  double render_s = 0, detect_s = 0, track_s = 0, validate_s = 0;
};

// Renders into OUT/dataset (replacing a dataset a previous run left there, unless
// run.render.resume; skipped for run.existing_dataset), runs run.detector into
// OUT/detections.json, tracks into OUT/track and validates into OUT/report (and the detections
// into OUT/report2d), announcing each stage on stderr before its progress line.
LoopResult run_closed_loop(const LoopRun& run, const std::filesystem::path& out);

// Why run.detector cannot feed run.track.method (a tracker that reads the images); empty when it
// can.
std::string detector_method_conflict(const LoopRun& run);

// The stage table (time, rate) and the headline metrics, then the report's path.
std::string loop_summary_text(const LoopResult& result);

// The options of `loop` that `demo` shares: the render and scoring groups (option_groups.h), the
// tracker's (track_cli.h), the detector's and --quiet.
struct LoopCliOptions {
  SeedOption seed;
  ScoringOptions scoring;
};
void add_loop_options(CLI::App* cmd, LoopRun& run, LoopCliOptions& cli);
// Applies the parsed LoopCliOptions to `run`.
void finish_loop_options(LoopRun& run, const LoopCliOptions& cli);

// The closed loop of one sweep point; an unknown tracker option, a bad value or an unknown
// detector is an Error naming `sweep_file` and the option (the detector with its line).
LoopRun loop_run_of(const LoopConfig& config, const std::filesystem::path& sweep_file, bool quiet);

}  // namespace simcap::cli
