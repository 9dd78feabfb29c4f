#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_bench(CLI::App& app, Action& action) {
  add_pending(app, action, "bench",
              "Measure throughput of the renderer, the tracker or inverse kinematics", "#4",
              "simcap bench render scenes/studio4.yaml");
}

}  // namespace simcap::cli
