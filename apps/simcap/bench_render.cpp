#include "apps/simcap/bench_commands.h"
#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_bench_render(CLI::App& bench, Action& action) {
  add_pending(bench, action, "render", "Renderer frames/s and the ratio to a bare Embree loop", "#4", "simcap bench render scenes/studio4.yaml");
}

}  // namespace simcap::cli
