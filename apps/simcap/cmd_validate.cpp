#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_validate(CLI::App& app, Action& action) {
  add_pending(
      app, action, "validate",
      "Score a tracker's output against a dataset's ground truth (metrics.json + report.html)",
      "#6", "simcap validate out/studio4 out/track -o out/report --fail-above 40");
}

}  // namespace simcap::cli
