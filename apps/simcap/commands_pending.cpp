#include "apps/simcap/commands_pending.h"

namespace simcap::cli {

void add_pending(CLI::App& app, Action& action, const std::string& name,
                 const std::string& description, const std::string& issue,
                 const std::string& example) {
  auto* cmd = app.add_subcommand(name, description + " [not built yet]");
  cmd->allow_extras();
  cmd->footer("Example:\n  " + example);
  cmd->callback([&action, name, issue] { action = [=] { return not_built_yet(name, issue); }; });
}

}  // namespace simcap::cli
