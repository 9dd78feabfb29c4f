#include "apps/simcap/option_groups.h"
#include "apps/simcap/number_checks.h"

namespace simcap::cli {

void SeedOption::apply(RenderOptions& options) const {
  if (option && option->count() > 0) options.seed = value;
}

void add_render_options(CLI::App* cmd, RenderOptions& options, SeedOption& seed) {
  cmd->add_option("--frames", options.frames, "Frames to render (unset: the whole motion)")
      ->check(positive_number());
  auto* motion = cmd->add_option("--motion", options.motion_override,
                                 "BVH file (or AMC file with --asf) that replaces the first "
                                 "actor's motion")
                     ->check(CLI::ExistingFile);
  cmd->add_option("--asf", options.motion_asf,
                  "ASF skeleton of the --motion AMC file (Acclaim, as the CMU database ships)")
      ->check(CLI::ExistingFile)
      ->needs(motion);
  // CLI11 reads "-1" into an unsigned seed as 2^64 - 1; a sign is a mistake, not that seed.
  seed.option =
      cmd->add_option("--seed", seed.value,
                      "Seed of anti-aliasing jitter and sensor noise (default: the scene's "
                      "render.seed)")
          ->check(non_negative_number());
  cmd->add_option("--set", options.overrides,
                  "Scene override key.path=value, repeatable (e.g. --set rig.count=6)");
  cmd->add_flag("--resume", options.resume,
                "Continue an interrupted render: frames whose files all exist are kept");
}

void add_scoring_options(CLI::App* cmd, ValidateOptions& options, ScoringOptions& scoring) {
  cmd->add_option("--failure-threshold", options.failure_threshold_mm,
                  "A frame whose MPJPE is above this (mm) counts as a tracking failure")
      ->capture_default_str()
      ->check(positive_number());
  cmd->add_flag("--no-media", scoring.no_media,
                "Metrics only: no overlay images or video (the RGB frames are not read)");
  cmd->add_option("--fail-above", scoring.fail_above_mm,
                  "Exit with status 4 when the MPJPE is above this many mm (for CI)")
      ->check(positive_number());
}

}  // namespace simcap::cli
