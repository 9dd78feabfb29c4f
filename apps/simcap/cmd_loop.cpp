#include <cstdio>

#include "apps/simcap/closed_loop.h"
#include "apps/simcap/commands.h"
#include "apps/simcap/fail_above.h"

namespace simcap::cli {
namespace {

struct LoopArgs {
  std::filesystem::path out;
  LoopRun run;
  LoopCliOptions cli;
};

int run_loop(LoopArgs& args) {
  finish_loop_options(args.run, args.cli);
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
  cmd->footer(
      "Exit status: 0 ok, 1 bad input, 4 MPJPE above --fail-above.\n"
      "Examples:\n"
      "  simcap loop scenes/studio4.yaml -o out/loop --frames 120\n"
      "  simcap loop scenes/occluders.yaml -o out/occ --silhouettes bgsub --fail-above 60\n"
      "  simcap loop scenes/studio8.yaml -o out/ring6 --set rig.count=6\n"
      "  simcap loop scenes/studio4.yaml -o out/mp --detector mediapipe --frames 60\n"
      "  simcap loop scenes/studio4.yaml -o out/tn --detector truth-noise --noise-px 2");
  cmd->callback([&action] { action = [] { return run_loop(args); }; });
}

}  // namespace simcap::cli
