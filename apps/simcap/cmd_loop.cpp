#include <algorithm>
#include <cstdio>

#include "apps/simcap/closed_loop.h"
#include "apps/simcap/commands.h"
#include "apps/simcap/fail_above.h"
#include "apps/simcap/gesture_summary.h"
#include "core/error.h"
#include "tracker/unzueta/gesture_job.h"

namespace simcap::cli {
namespace {

namespace fs = std::filesystem;

struct LoopArgs {
  fs::path out;
  LoopRun run;
  LoopCliOptions cli;
  int subjects = 1;
};

// A gesture corpus (Unzueta ch. 5): the loop once per subject, each rendered with its own seed
// (the scene's `vary` draws another body and another order, speed and size of the gestures),
// then spotting and recognition leave-one-subject-out over the tracks.
int run_gesture_loop(LoopArgs& args) {
  const std::uint64_t first = args.run.render.seed.value_or(1);
  std::vector<tracker::GestureSource> sources;
  double worst_mpjpe = 0;
  for (int k = 0; k < args.subjects; ++k) {
    LoopRun run = args.run;
    run.render.seed = first + k;
    const fs::path out = args.out / ("subject" + std::to_string(*run.render.seed));
    if (!run.quiet) {
      std::fprintf(stderr, "loop: subject %d of %d (seed %llu) -> %s\n", k + 1, args.subjects,
                   static_cast<unsigned long long>(*run.render.seed), out.string().c_str());
    }
    const LoopResult r = run_closed_loop(run, out);
    if (!fs::exists(r.dataset / "gt" / "gestures.csv")) {
      throw Error(args.run.scene.string() + ": --subjects scores gestures, but " +
                  (r.dataset / "gt" / "gestures.csv").string() +
                  " is missing: no gesture lies in the rendered frames (the scene's actors "
                  "have no gesture motion, as scenes/gestures.yaml's has, or --frames or "
                  "render.first_frame leave its gestures out)");
    }
    std::printf("%s", loop_summary_text(r).c_str());
    worst_mpjpe = std::max(worst_mpjpe, r.validate.evaluation.mpjpe_mm);
    sources.push_back({r.dataset, out / "track"});
  }
  const fs::path out = args.out / "gestures";
  const tracker::GestureResults g = tracker::run_gestures(sources, out, {});
  const int status = fail_above_status("loop", worst_mpjpe, args.cli.scoring.fail_above_mm);
  std::printf("%s", gestures_summary_text(g, out).c_str());
  return status;
}

int run_loop(LoopArgs& args) {
  finish_loop_options(args.run, args.cli);
  if (args.subjects > 1) return run_gesture_loop(args);
  const LoopResult r = run_closed_loop(args.run, args.out);
  std::printf("%s", loop_summary_text(r).c_str());
  return fail_above_status("loop", r.validate.evaluation.mpjpe_mm, args.cli.scoring.fail_above_mm);
}

}  // namespace

void add_loop(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("loop", "Render, track and validate in one command");
  static LoopArgs args;
  cmd->add_option("scene", args.run.scene, "Scene file (YAML; see scenes/README.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args.out, "Output folder: dataset/, track/, report/")->required();
  add_loop_options(cmd, args.run, args.cli);
  cmd->add_option("--subjects", args.subjects,
                  "A gesture corpus: the loop for N subjects (seeds S, S+1, ...; S = --seed or "
                  "1) into OUT/subjectSEED, then gesture spotting and recognition "
                  "leave-one-subject-out into OUT/gestures (as simcap gestures)")
      ->check(CLI::Range(1, 100))
      ->capture_default_str();
  cmd->footer(
      "Exit status: 0 ok, 1 bad input, 4 MPJPE above --fail-above.\n"
      "Examples:\n"
      "  simcap loop scenes/studio4.yaml -o out/loop --frames 120\n"
      "  simcap loop scenes/occluders.yaml -o out/occ --silhouettes bgsub --fail-above 60\n"
      "  simcap loop scenes/studio8.yaml -o out/ring6 --set rig.count=6\n"
      "  simcap loop scenes/studio4.yaml -o out/mp --detector mediapipe --frames 60\n"
      "  simcap loop scenes/studio4.yaml -o out/tn --detector truth-noise --noise-px 2\n"
      "  simcap loop scenes/gestures.yaml -o out/gest --subjects 3 --method sik --effectors "
      "depth\n"
      "With --subjects N > 1 the last stdout line is spotting_f1=F recognition_accuracy=A.");
  cmd->callback([&action] { action = [] { return run_loop(args); }; });
}

}  // namespace simcap::cli
