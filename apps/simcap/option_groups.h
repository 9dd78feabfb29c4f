// Option groups that several subcommands share, declared once so that each option reads and acts
// the same everywhere: scene rendering (render, loop, demo) and scoring (validate, loop, demo).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>

#include "sim/render_job.h"
#include "validate/validate_job.h"

namespace simcap::cli {

// --seed, which replaces the scene's render.seed only when given.
struct SeedOption {
  std::uint64_t value = 0;
  CLI::Option* option = nullptr;
  void apply(RenderOptions& options) const;
};

// --frames, --motion, --seed, --set and --resume.
void add_render_options(CLI::App* cmd, RenderOptions& options, SeedOption& seed);

// The scoring options that are not ValidateOptions themselves.
struct ScoringOptions {
  bool no_media = false;
  std::optional<double> fail_above_mm;  // exit status 4 above it (fail_above.h)
  void apply(ValidateOptions& options) const { options.media = !no_media; }
};

// --failure-threshold, --no-media and --fail-above.
void add_scoring_options(CLI::App* cmd, ValidateOptions& options, ScoringOptions& scoring);

}  // namespace simcap::cli
