#include "apps/simcap/sik_cue_options.h"

#include "apps/simcap/choice_option.h"
#include "apps/simcap/number_checks.h"

namespace simcap::cli {

void add_sik_cue_options(CLI::App* cmd, double& travel, SikSpineBend& bend,
                         const std::string& scope) {
  cmd->add_option("--pelvis-travel", travel,
                  scope +
                      "weight of the pelvis X that faces the pelvis' last 0.3 m of travel, times "
                      "its agreement with the limbs' X (none for side or backward steps); 0: the "
                      "thesis' pelvis estimate")
      ->check(non_negative_number())
      ->capture_default_str();
  add_choice(cmd, "--spine-bend", bend, kSikSpineBends,
             scope +
                 "how far the spine flexes when the pelvis-head line is shorter than the neutral "
                 "spine: lean (the thesis' flexion times the sine of the line's forward lean from "
                 "the vertical, all of it past the horizontal, none leaning back; the length left "
                 "is split between pelvis and head) or thesis (all the flexion that length needs, "
                 "eqs. 8-9)");
}

}  // namespace simcap::cli
