#include "apps/simcap/bench_commands.h"
#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_bench_ik(CLI::App& bench, Action& action) {
  add_pending(bench, action, "ik", "SIK, CCD and DLS time per frame", "#7", "simcap bench ik");
}

}  // namespace simcap::cli
