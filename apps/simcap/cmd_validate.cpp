#include <cstdio>
#include <filesystem>
#include <string>

#include "apps/simcap/choice_option.h"
#include "apps/simcap/commands.h"
#include "apps/simcap/fail_above.h"
#include "apps/simcap/option_groups.h"
#include "core/error.h"
#include "validate/keypoint_report.h"
#include "validate/summary_text.h"
#include "validate/validate_job.h"

namespace simcap::cli {
namespace {

struct ValidateArgs {
  std::filesystem::path dataset, track, out, detections;
  ValidateOptions options;
  ScoringOptions scoring;
  DetectionValidateOptions detection;
  KeypointLayoutId layout = KeypointLayoutId::coco17;
  bool layout_given = false;
};

int run_detection_validate(const ValidateArgs& args) {
  DetectionValidateOptions options = args.detection;
  if (args.layout_given) options.layout = args.layout;
  const DetectionValidation v =
      validate_detections(args.dataset, args.detections, args.out, options);
  std::printf("simcap validate: %s against %s\n%s", args.detections.string().c_str(),
              args.dataset.string().c_str(), keypoint_summary_text(v.scores).c_str());
  std::printf("report: %s\nscores: %s, %s\n", v.html.string().c_str(), v.json.string().c_str(),
              v.csv.string().c_str());
  return 0;
}

int run_validate(const ValidateArgs& args) {
  if (args.track.empty() == args.detections.empty()) {
    throw Error(std::string("validate: give either TRACK or --detections FILE (got ") +
                (args.track.empty() ? "neither" : "both") + ")");
  }
  if (!args.detections.empty()) return run_detection_validate(args);
  ValidateOptions options = args.options;
  args.scoring.apply(options);
  const ValidateSummary s = validate_dataset(args.dataset, args.track, args.out, options);
  std::printf("simcap validate: %s against %s\n%s", args.track.string().c_str(),
              args.dataset.string().c_str(), metrics_summary_text(s.evaluation).c_str());
  if (s.effectors) std::printf("%s", effector_summary_text(*s.effectors).c_str());
  std::printf("report: %s\nmetrics: %s\n", s.report_html.string().c_str(),
              s.metrics_json.string().c_str());
  return fail_above_status("validate", s.evaluation.mpjpe_mm, args.scoring.fail_above_mm);
}

}  // namespace

void add_validate(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "validate",
      "Score a tracker's output against a dataset's ground truth (metrics.json + report.html)");
  static ValidateArgs args;
  cmd->add_option("dataset", args.dataset, "Dataset folder written by simcap render")->required();
  cmd->add_option("track", args.track, "Track folder written by simcap track (joints3d.csv)");
  auto* detections = cmd->add_option(
      "--detections", args.detections,
      "Score a 2D keypoint detector instead of a track: COCO results .json, OpenPose folder or "
      ".csv (validate/README.md)");
  add_choice(cmd, "--layout", args.layout, kKeypointLayouts,
             "Keypoint layout of --detections (default: from the keypoint count or names)")
      ->default_str("")
      ->each([&](const std::string&) { args.layout_given = true; })
      ->needs(detections);
  cmd->add_option("--actor", args.detection.actor,
                  "With --detections: the actor scored (default: the first)")
      ->needs(detections);
  cmd->add_option("--min-keypoint-score", args.detection.min_keypoint_score,
                  "With --detections: a keypoint is detected when its score is above this")
      ->capture_default_str()
      ->needs(detections);
  cmd->add_option("-o,--output", args.out, "Report folder (metrics.json, report.html, MP4)")
      ->required();
  add_scoring_options(cmd, args.options, args.scoring);
  cmd->add_option("--overlay-frames", args.options.overlay_frames,
                  "Frames drawn over every camera in the report (the worst one among them)")
      ->capture_default_str()
      ->check(CLI::Range(1, 50));
  cmd->add_option("--video-camera", args.options.video_camera,
                  "Camera of the overlay video (default: the first camera)");
  cmd->add_option("--video-frames", args.options.video_max_frames,
                  "At most this many frames in the overlay video")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_flag("-q,--quiet", args.options.quiet, "No progress on stderr");
  cmd->footer(
      "Exit status: 0 ok, 1 bad input, 4 MPJPE above --fail-above.\n"
      "With --detections the report is of 2D keypoints: COCO AP, PCK, pixel errors, misses and\n"
      "left/right swaps per keypoint and visibility class (keypoints2d.json, .csv, report.html).\n"
      "Examples:\n  simcap validate out/studio4 out/track -o out/report --fail-above 40\n"
      "  simcap detections out/studio4 -o det.json --noise-px 2\n"
      "  simcap validate out/studio4 --detections det.json -o out/report2d");
  cmd->callback([&action] { action = [] { return run_validate(args); }; });
}

}  // namespace simcap::cli
