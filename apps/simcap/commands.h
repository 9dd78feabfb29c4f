// The subcommands of the simcap program. Each lives in its own cmd_*.cpp, declares its options
// on the CLI11 app and, when the user selects it, stores the work to run in `action`.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace simcap::cli {

using Action = std::function<int()>;

void add_render(CLI::App& app, Action& action);
void add_track(CLI::App& app, Action& action);
void add_validate(CLI::App& app, Action& action);
void add_loop(CLI::App& app, Action& action);
void add_demo(CLI::App& app, Action& action);
void add_stress(CLI::App& app, Action& action);
void add_bench(CLI::App& app, Action& action);
void add_model(CLI::App& app, Action& action);
void add_motion(CLI::App& app, Action& action);
void add_ik_eval(CLI::App& app, Action& action);
void add_gestures(CLI::App& app, Action& action);
void add_export(CLI::App& app, Action& action);
void add_detections(CLI::App& app, Action& action);
void add_collect(CLI::App& app, Action& action);
void add_version(CLI::App& app, Action& action);

}  // namespace simcap::cli
