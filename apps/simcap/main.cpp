// simcap: render labelled multi-camera sequences of H-Anim humanoids, track them, validate.
#include <exception>
#include <iostream>

#include "apps/simcap/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
  using namespace simcap::cli;
  CLI::App app{
      "simcap: a testbed for markerless human motion capture.\n"
      "Renders H-Anim humanoids animated by real motion capture in multi-camera rooms, writes\n"
      "exactly consistent ground truth, runs trackers on the frames and validates them."};
  app.require_subcommand(1);
  app.footer(
      "Examples:\n"
      "  simcap demo                                  closed loop on the built-in default\n"
      "  simcap render scenes/studio4.yaml -o out/d   render a dataset\n"
      "  simcap <command> --help                      options of one command");
  Action action;
  add_render(app, action);
  add_track(app, action);
  add_validate(app, action);
  add_loop(app, action);
  add_demo(app, action);
  add_stress(app, action);
  add_bench(app, action);
  add_model(app, action);
  add_motion(app, action);
  add_ik_eval(app, action);
  add_gestures(app, action);
  add_export(app, action);
  add_detections(app, action);
  add_collect(app, action);
  add_version(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11's own codes (105, 106, ...) would break the documented "1: bad input"; --help is 0.
    return app.exit(e) == 0 ? 0 : 1;
  }
  try {
    return action ? action() : 0;
  } catch (const simcap::Error& e) {
    std::cerr << "simcap: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "simcap: internal error: " << e.what() << "\n";
    return 3;
  }
}
