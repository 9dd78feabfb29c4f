#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <tuple>

#include "apps/simcap/closed_loop.h"
#include "apps/simcap/commands.h"
#include "core/error.h"
#include "scenes/scene.h"
#include "validate/sweep.h"

namespace simcap::cli {
namespace fs = std::filesystem;

namespace {

struct StressArgs {
  fs::path sweep, out;
  std::optional<int> frames;  // replaces the file's frames (a quick look at a long sweep)
  bool keep_datasets = false;
  bool quiet = false;
};

// Points that render the same thing share one dataset: only the tracker settings differ.
using RenderKey =
    std::tuple<fs::path, int, std::optional<std::uint64_t>, fs::path, std::vector<std::string>>;

RenderKey render_key(const LoopConfig& c) {
  return {c.scene, c.frames, c.seed, c.motion, c.scene_overrides};
}

// Loads the point's scene with its overrides; a bad override is named with its line in the sweep
// file, which the scene loader does not know.
void check_scene_overrides(const LoopConfig& c, const fs::path& sweep_file) {
  try {
    load_scene(c.scene, c.scene_overrides);
    return;
  } catch (const Error&) {
  }
  // The first override after which the scene no longer loads is the one to blame.
  for (size_t n = 0; n <= c.scene_overrides.size(); ++n) {
    try {
      load_scene(c.scene, {c.scene_overrides.begin(), c.scene_overrides.begin() + n});
    } catch (const Error& e) {
      if (n == 0) throw;
      const int line = n <= c.scene_override_lines.size() ? c.scene_override_lines[n - 1] : 0;
      throw_input_error(sweep_file, line, "", e.what());
    }
  }
}

int run_stress(const StressArgs& args) {
  SweepSpec spec = load_sweep(args.sweep);
  if (args.frames) spec.base.frames = *args.frames;
  const std::vector<SweepPoint> points = sweep_points(spec);
  // Every point's scene and tracker options are checked before the first one runs.
  for (const auto& p : points) {
    loop_run_of(p.config, args.sweep, args.quiet);
    check_scene_overrides(p.config, args.sweep);
  }
  std::map<RenderKey, fs::path> rendered;
  const SweepPointRunner run = [&](const SweepPoint& point, const fs::path& dir) {
    LoopRun loop = loop_run_of(point.config, args.sweep, args.quiet);
    const auto cached = rendered.find(render_key(point.config));
    if (cached != rendered.end()) loop.existing_dataset = cached->second;
    const LoopResult r = run_closed_loop(loop, dir);
    rendered.emplace(render_key(point.config), r.dataset);
    SweepOutcome o;
    o.evaluation = r.validate.evaluation;
    o.report = r.validate.report_html;
    if (r.keypoints2d) {
      o.keypoints2d = r.keypoints2d->scores;
      o.report2d = r.keypoints2d->html;
    }
    o.render_s = r.render_s;
    o.track_s = r.track_s;
    o.validate_s = r.validate_s;
    return o;
  };
  const auto outcomes = run_sweep(spec, args.out, run, args.quiet);
  if (!args.keep_datasets) {
    for (const auto& [key, dataset] : rendered) fs::remove_all(dataset);
  }
  std::printf("simcap stress: %s\n",
              spec.title.empty() ? args.sweep.string().c_str() : spec.title.c_str());
  std::fputs(sweep_table_text(spec, points, outcomes).c_str(), stdout);
  std::printf("table: %s\nplot: %s\n", (args.out / "table.html").string().c_str(),
              (args.out / "mpjpe.svg").string().c_str());
  // A point may fail as a measurement (too few cameras to track); a sweep that measured
  // nothing is an error.
  if (std::none_of(outcomes.begin(), outcomes.end(),
                   [](const SweepOutcome& o) { return o.evaluation.has_value(); })) {
    std::fprintf(stderr, "simcap stress: every point failed (see above)\n");
    return 1;
  }
  return 0;
}

}  // namespace

void add_stress(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "stress",
      "Run a parameter sweep (cameras, occluders, silhouette noise) with tables and plots");
  static StressArgs args;
  cmd->add_option("sweep", args.sweep, "Sweep file (YAML; see stress/*.yaml)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args.out,
                  "Output folder: table.csv, table.html, mpjpe.svg, timings.csv, points/")
      ->required();
  cmd->add_option("--frames", args.frames,
                  "Render N frames per point instead of the sweep file's frames (a quick run)")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--keep-datasets", args.keep_datasets,
                "Keep each point's rendered dataset (by default only tracks and reports stay)");
  cmd->add_flag("-q,--quiet", args.quiet, "No progress on stderr");
  cmd->footer(
      "A sweep file names a base scene, frames and tracker options, and what to vary: scene keys\n"
      "(rig.count: [2, 3, 4]), the scene file, or tracker options (track.silhouettes). Points\n"
      "that render the same scene share one rendered dataset. A point that fails is a row of the\n"
      "table; the command exits 1 only when every point failed. A `detector:` (truth-noise or\n"
      "mediapipe) feeds 2D keypoints to the triangulate tracker; the tables then show its 2D\n"
      "scores by visibility class too.\n"
      "Examples:\n"
      "  simcap stress stress/cameras.yaml -o out/stress-cameras\n"
      "  simcap stress stress/occlusion.yaml -o out/stress-occlusion\n"
      "  simcap stress stress/silhouettes.yaml -o out/stress-silhouettes\n"
      "  simcap stress stress/motions.yaml -o out/stress-motions\n"
      "  simcap stress stress/detectors.yaml -o out/stress-detectors\n"
      "  simcap stress stress/detectors.yaml -o out/stress-detectors-quick --frames 20");
  cmd->callback([&action] { action = [] { return run_stress(args); }; });
}

}  // namespace simcap::cli
