// The command-line options that choose SIK's cues beyond the thesis (--pelvis-travel,
// --spine-bend), shared by ik-eval and track so that both commands mean one solver by "SIK".
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "tracker/unzueta/sik_spine.h"

namespace simcap::cli {

// Adds both options to `cmd`, writing `travel` and `bend`; `scope` starts their help text (the
// methods they apply to, e.g. "sik, tgbsik: ").
void add_sik_cue_options(CLI::App* cmd, double& travel, SikSpineBend& bend,
                         const std::string& scope);

}  // namespace simcap::cli
