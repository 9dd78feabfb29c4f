#include "apps/simcap/bench_commands.h"

namespace simcap::cli {

void add_bench(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "bench", "Measure throughput of the renderer, the tracker or inverse kinematics");
  cmd->require_subcommand(1);
  cmd->footer(
      "Examples:\n"
      "  simcap bench render scenes/studio4.yaml\n"
      "  simcap bench track out/studio4\n"
      "  simcap bench ik");
  add_bench_render(*cmd, action);
  add_bench_track(*cmd, action);
  add_bench_ik(*cmd, action);
}

}  // namespace simcap::cli
