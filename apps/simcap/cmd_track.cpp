#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_track(CLI::App& app, Action& action) {
  add_pending(app, action, "track", "Run a tracker on a dataset and write its joints3d.csv", "#5",
              "simcap track out/studio4 -o out/track --method moschini --init gt");
}

}  // namespace simcap::cli
