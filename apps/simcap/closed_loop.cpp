#include "apps/simcap/closed_loop.h"
#include "apps/simcap/track_cli.h"

#include <chrono>
#include <cstdio>

#include "core/error.h"
#include "validate/summary_text.h"

namespace simcap::cli {
namespace fs = std::filesystem;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void announce(bool quiet, int stage, const char* what) {
  if (!quiet) std::fprintf(stderr, "[%d/3] %s\n", stage, what);
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

  auto t = std::chrono::steady_clock::now();
  if (run.existing_dataset.empty()) {
    announce(run.quiet, 1, "render");
    r.dataset = out / "dataset";
    r.render = render_dataset(run.scene, r.dataset, render);
    r.render_s = seconds_since(t);
  } else {
    announce(run.quiet, 1, ("render: reusing " + run.existing_dataset.string()).c_str());
    r.dataset = run.existing_dataset;
  }

  track.method = tracker::resolve_method(track.method, tracker::Dataset(r.dataset));
  announce(run.quiet, 2, ("track (" + track_options_text(track) + ")").c_str());
  t = std::chrono::steady_clock::now();
  r.track = tracker::track_dataset(r.dataset, out / "track", track);
  r.track_s = seconds_since(t);

  announce(run.quiet, 3, "validate");
  t = std::chrono::steady_clock::now();
  r.validate = validate_dataset(r.dataset, out / "track", out / "report", validate);
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
  std::snprintf(buf, sizeof buf, "  %-10s %7.1f s  %.1f frames/s (%d re-initialization%s)\n",
                "track", r.track_s, r.track.frames / r.track_s, r.track.reinitializations,
                r.track.reinitializations == 1 ? "" : "s");
  s += buf;
  std::snprintf(buf, sizeof buf, "  %-10s %7.1f s\n", "validate", r.validate_s);
  s += buf;
  s += "metrics:\n" + metrics_summary_text(r.validate.evaluation);
  s += "report: " + r.validate.report_html.string() + "\n";
  return s;
}

void add_loop_options(CLI::App* cmd, LoopRun& run, LoopCliOptions& cli) {
  add_render_options(cmd, run.render, cli.seed);
  add_track_options(cmd, run.track, TrackOptionScope::loop);
  add_scoring_options(cmd, run.validate, cli.scoring);
  cmd->add_flag("-q,--quiet", run.quiet, "No progress on stderr");
}

void finish_loop_options(LoopRun& run, const LoopCliOptions& cli) {
  cli.seed.apply(run.render);
  cli.scoring.apply(run.validate);
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
  apply_sweep_track_options(c.track_options, sweep_file, run.track);
  return run;
}

}  // namespace simcap::cli
