#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_render(CLI::App& app, Action& action) {
  add_pending(
      app, action, "render",
      "Render a dataset (RGB, depth, masks, part labels, joints, calibration) from a scene file",
      "#4", "simcap render scenes/studio4.yaml -o out/studio4 --frames 60");
}

}  // namespace simcap::cli
