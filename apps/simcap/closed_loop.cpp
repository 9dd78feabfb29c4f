#include "apps/simcap/closed_loop.h"
#include "apps/simcap/choice_option.h"
#include "apps/simcap/track_cli.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>

#include "core/error.h"
#include "validate/summary_text.h"

namespace simcap::cli {
namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void announce(bool quiet, int stage, int stages, const std::string& what) {
  if (!quiet) std::fprintf(stderr, "[%d/%d] %s\n", stage, stages, what.c_str());
}

}  // namespace

LoopResult run_closed_loop(const LoopRun& run, const fs::path& out) {
  LoopResult r;
  r.scene = run.scene;
  r.out = out;
  RenderOptions render = run.render;
  render.overwrite = !render.resume;
  render.quiet = run.quiet;
  tracker::TrackOptions track = run.track;
  track.quiet = run.quiet;
  ValidateOptions validate = run.validate;
  validate.quiet = run.quiet;
  r.detector = run.detector;
  const bool detect = run.detector != LoopDetector::none;
  const int stages = detect ? 4 : 3;
  if (!detect && track.method == tracker::TrackMethod::triangulate &&
      track.triangulate.detections.empty()) {
    throw Error(
        "--method triangulate needs 2D keypoints of the dataset the loop renders: --detector "
        "mediapipe or truth-noise (checked before anything is rendered)");
  }
  if (detect) {
    // Checked before anything is rendered.
    if (const std::string why = detector_method_conflict(run); !why.empty()) throw Error(why);
    track.method = tracker::TrackMethod::triangulate;
    track.triangulate.detections = out / "detections.json";
  }

  if (run.existing_dataset.empty()) {
    // The tracker's refusals that the scene decides (cameras, actors), before anything is
    // rendered.
    const Scene scene = load_for_render(run.scene, render);
    tracker::DatasetShape shape{static_cast<int>(scene.cameras.size()), {}};
    for (const Actor& a : scene.actors) shape.actors.push_back(a.name);
    tracker::check_shape(track, shape, run.scene.string());
  }
  auto t = std::chrono::steady_clock::now();
  if (run.existing_dataset.empty()) {
    announce(run.quiet, 1, stages, "render");
    r.dataset = out / "dataset";
    r.render = render_dataset(run.scene, r.dataset, render);
    r.render_s = seconds_since(t);
  } else {
    announce(run.quiet, 1, stages, "render: reusing " + run.existing_dataset.string());
    r.dataset = run.existing_dataset;
  }

  if (detect) {
    announce(run.quiet, 2, stages,
             "detect (" + std::string(name_of(kLoopDetectors, run.detector)) + ")");
    t = std::chrono::steady_clock::now();
    run_loop_detector(run.detector, r.dataset, track.triangulate.detections, run.truth_noise,
                      run.quiet);
    r.detect_s = seconds_since(t);
  }

  track.method = tracker::resolve_method(track.method, tracker::Dataset(r.dataset));
  announce(run.quiet, stages - 1, stages, "track (" + track_options_text(track) + ")");
  t = std::chrono::steady_clock::now();
  r.track = tracker::track_dataset(r.dataset, out / "track", track);
  r.track_s = seconds_since(t);

  announce(run.quiet, stages, stages, "validate");
  t = std::chrono::steady_clock::now();
  r.validate = validate_dataset(r.dataset, out / "track", out / "report", validate);
  if (detect) {
    r.keypoints2d =
        validate_detections(r.dataset, track.triangulate.detections, out / "report2d", {});
  }
  r.validate_s = seconds_since(t);
  return r;
}

std::string loop_summary_text(const LoopResult& r) {
  char buf[512];
  std::string s;
  std::snprintf(buf, sizeof buf, "simcap loop: %s -> %s\n", r.scene.string().c_str(),
                r.out.string().c_str());
  s += buf;
  std::snprintf(buf, sizeof buf, "  %-10s %9s  %s\n", "stage", "time", "throughput");
  s += buf;
  if (r.render.frames > 0) {
    std::snprintf(buf, sizeof buf, "  %-10s %7.1f s  %.1f frames/s (%d frames x %d cameras)\n",
                  "render", r.render_s, r.render.frames / r.render_s, r.render.frames,
                  r.render.cameras);
  } else {
    std::snprintf(buf, sizeof buf, "  %-10s %9s  reused %s\n", "render", "-",
                  r.dataset.string().c_str());
  }
  s += buf;
  if (r.detector != LoopDetector::none) {
    std::snprintf(buf, sizeof buf, "  %-10s %7.1f s  %s\n", "detect", r.detect_s,
                  std::string(name_of(kLoopDetectors, r.detector)).c_str());
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "  %-10s %7.1f s  %.1f frames/s (%d re-initialization%s)\n",
                "track", r.track_s, r.track.frames / r.track_s, r.track.reinitializations,
                r.track.reinitializations == 1 ? "" : "s");
  s += buf;
  s += without_person_warning(r.track);
  std::snprintf(buf, sizeof buf, "  %-10s %7.1f s\n", "validate", r.validate_s);
  s += buf;
  s += "metrics:\n" + metrics_summary_text(r.validate.evaluation);
  s += "report: " + r.validate.report_html.string() + "\n";
  if (r.keypoints2d) {
    s += "2D keypoints of the detector:\n" + keypoint_summary_text(r.keypoints2d->scores);
    s += "2D report: " + r.keypoints2d->html.string() + "\n";
  }
  return s;
}

void add_loop_options(CLI::App* cmd, LoopRun& run, LoopCliOptions& cli) {
  add_render_options(cmd, run.render, cli.seed);
  add_track_options(cmd, run.track, TrackOptionScope::loop);
  refuse_other_methods_options(cmd, run.track);
  add_scoring_options(cmd, run.validate, cli.scoring);
  add_choice(cmd, "--detector", run.detector, kLoopDetectors,
             "2D keypoints triangulated by --method triangulate instead of a tracker reading the "
             "images: mediapipe (scripts/detect_mediapipe; set-up: make setup-mediapipe) or "
             "truth-noise (the true COCO-17 keypoints plus --noise-px)");
  cmd->add_option("--noise-px", run.truth_noise.sigma_px,
                  "--detector truth-noise: standard deviation of each pixel coordinate's noise")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", run.quiet, "No progress on stderr");
}

void finish_loop_options(LoopRun& run, const LoopCliOptions& cli) {
  cli.seed.apply(run.render);
  cli.scoring.apply(run.validate);
}

std::string detector_method_conflict(const LoopRun& run) {
  if (run.detector == LoopDetector::none || run.track.method == tracker::TrackMethod::automatic ||
      run.track.method == tracker::TrackMethod::triangulate) {
    return "";
  }
  return "--detector " + std::string(name_of(kLoopDetectors, run.detector)) +
         ": its keypoints are triangulated, so --method must be triangulate (or unset), not " +
         std::string(name_of(tracker::kTrackMethods, run.track.method));
}

LoopRun loop_run_of(const LoopConfig& c, const fs::path& sweep_file, bool quiet) {
  LoopRun run;
  run.scene = c.scene;
  run.render.frames = c.frames;
  run.render.seed = c.seed;
  run.render.motion_override = c.motion;
  run.render.overrides = c.scene_overrides;
  run.validate.failure_threshold_mm = c.failure_threshold_mm;
  run.quiet = quiet;
  apply_sweep_track_options(c.track_options, c.track_option_lines, sweep_file, run.track);
  if (!c.detector.name.empty()) {
    const auto* d = std::find_if(kLoopDetectors.begin(), kLoopDetectors.end(),
                                 [&](const auto& e) { return e.first == c.detector.name; });
    if (d == kLoopDetectors.end()) {
      throw_input_error(
          sweep_file, c.detector.line, "detector",
          "unknown detector '" + c.detector.name + "'; expected " + choices_text(kLoopDetectors));
    }
    run.detector = d->second;
    run.truth_noise = {c.detector.noise_px, c.detector.seed};
    if (const std::string why = detector_method_conflict(run); !why.empty()) {
      throw_input_error(sweep_file, c.detector.line, "detector",
                        "track.method must be triangulate (or unset): the detector's keypoints "
                        "are triangulated");
    }
  }
  return run;
}

}  // namespace simcap::cli
