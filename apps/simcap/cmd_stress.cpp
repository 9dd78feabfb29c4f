#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_stress(CLI::App& app, Action& action) {
  add_pending(app, action, "stress",
              "Run a parameter sweep (cameras, occluders, silhouette noise) with tables and plots",
              "#6", "simcap stress stress/cameras.yaml -o out/cameras");
}

}  // namespace simcap::cli
