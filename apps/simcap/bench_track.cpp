#include "apps/simcap/bench_commands.h"
#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_bench_track(CLI::App& bench, Action& action) {
  add_pending(bench, action, "track", "Tracker frames/s per stage on a dataset", "#5", "simcap bench track out/studio4");
}

}  // namespace simcap::cli
