#include <cstdio>
#include <filesystem>

#include "apps/simcap/closed_loop.h"
#include "apps/simcap/commands.h"
#include "apps/simcap/fail_above.h"
#include "scenes/scene.h"

namespace simcap::cli {
namespace {

// Frames of the demo: 8 s of the CMU walk at the scene's 30 frames/s, enough to see the tracker
// through a whole crossing of the room while the loop stays within its time budget (ARCHITECTURE:
// under 3 minutes on 2 cores).
constexpr int kDemoFrames = 240;

struct DemoArgs {
  std::filesystem::path out = "out/demo";
  LoopRun run;
  LoopCliOptions cli;
};

int run_demo(DemoArgs& args) {
  args.run.scene = shipped_scene_path("studio4");
  finish_loop_options(args.run, args.cli);
  if (!args.run.quiet) {
    std::fprintf(stderr,
                 "simcap demo: render %d frames of the CMU 131_01 walk in the 4-camera studio "
                 "(%s), track them with the %s tracker and validate against the ground truth\n",
                 args.run.render.frames, args.run.scene.string().c_str(),
                 std::string(name_of(tracker::kTrackMethods, args.run.track.method)).c_str());
  }
  const LoopResult r = run_closed_loop(args.run, args.out);
  std::printf("%s", loop_summary_text(r).c_str());
  return fail_above_status("demo", r.validate.evaluation.mpjpe_mm, args.cli.scoring.fail_above_mm);
}

}  // namespace

void add_demo(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "demo", "Run the closed loop (render, track, validate) on the built-in default scene");
  static DemoArgs args;
  args.run.render.frames = kDemoFrames;
  args.run.track.method = tracker::TrackMethod::moschini;
  cmd->add_option("-o,--output", args.out, "Output folder: dataset/, track/, report/")
      ->capture_default_str();
  add_loop_options(cmd, args.run, args.cli);
  cmd->get_option("--frames")->capture_default_str()->description("Frames to render");
  cmd->footer(
      "The default scene is scenes/studio4.yaml: a 4 m x 4 m room, four VGA cameras in its\n"
      "upper corners, one actor walking the CMU 131_01 clip. Prints the metrics and the path of\n"
      "report.html.\n"
      "Examples:\n"
      "  simcap demo\n"
      "  simcap demo -o out/demo-bgsub --silhouettes bgsub --frames 120");
  cmd->callback([&action] { action = [] { return run_demo(args); }; });
}

}  // namespace simcap::cli
