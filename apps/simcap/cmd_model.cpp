#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_model(CLI::App& app, Action& action) {
  add_pending(app, action, "model", "Inspect and export the humanoid model (X3D H-Anim, URDF, BVH)",
              "#3", "simcap model urdf -o body.urdf");
}

}  // namespace simcap::cli
