// Registration of a subcommand whose capability is not built yet: it has its --help and example,
// and running it says which issue brings it and exits 2.
#pragma once

#include "apps/simcap/commands.h"

namespace simcap::cli {

void add_pending(CLI::App& app, Action& action, const std::string& name,
                 const std::string& description, const std::string& issue,
                 const std::string& example);

}  // namespace simcap::cli
