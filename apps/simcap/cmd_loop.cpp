#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_loop(CLI::App& app, Action& action) {
  add_pending(app, action, "loop", "Render, track and validate in one command", "#6",
              "simcap loop scenes/studio4.yaml -o out/loop --frames 120");
}

}  // namespace simcap::cli
