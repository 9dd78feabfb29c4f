#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_ik_eval(CLI::App& app, Action& action) {
  add_pending(app, action, "ik-eval",
              "Evaluate an inverse-kinematics solver on a motion clip (Unzueta's Table 10)", "#7",
              "simcap ik-eval walk.bvh --method sik -o out/ik");
}

}  // namespace simcap::cli
