#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_motion(CLI::App& app, Action& action) {
  add_pending(app, action, "motion", "Inspect and convert motion files (BVH dump, retargeting)",
              "#3", "simcap motion dump walk.bvh -o joints.csv");
}

}  // namespace simcap::cli
