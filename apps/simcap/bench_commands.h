// Back-ends of `simcap bench render|track|ik`, one per file so that each stage's owner can
// change its own. Each returns the process exit code.
#pragma once

#include <CLI/CLI.hpp>

#include "apps/simcap/commands.h"

namespace simcap::cli {

void add_bench_render(CLI::App& bench, Action& action);
void add_bench_track(CLI::App& bench, Action& action);
void add_bench_ik(CLI::App& bench, Action& action);

}  // namespace simcap::cli
