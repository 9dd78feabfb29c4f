#include <cstdio>
#include <filesystem>

#include "apps/simcap/commands.h"
#include "apps/simcap/option_groups.h"
#include "sim/render_job.h"

namespace simcap::cli {
namespace {

struct RenderArgs {
  std::filesystem::path scene, out;
  RenderOptions options;
  SeedOption seed;
};

int run_render(RenderArgs& args) {
  args.seed.apply(args.options);
  const RenderSummary s = render_dataset(args.scene, args.out, args.options);
  std::printf("simcap render: %d frames x %d cameras in %.1f s (%.1f frames/s) -> %s\n", s.frames,
              s.cameras, s.seconds, s.frames / s.seconds, s.dataset.string().c_str());
  return 0;
}

}  // namespace

void add_render(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand(
      "render",
      "Render a dataset (RGB, depth, masks, part labels, joints, calibration) from a scene file");
  static RenderArgs args;
  cmd->add_option("scene", args.scene, "Scene file (YAML; see scenes/README.md)")->required();
  cmd->add_option("-o,--output", args.out, "Dataset folder to write (new or empty)")->required();
  add_render_options(cmd, args.options, args.seed);
  cmd->add_option("--cameras", args.options.cameras,
                  "Only these cameras of the scene's rig, comma-separated (e.g. cam00,cam02), "
                  "with their names and images")
      ->delimiter(',');
  cmd->add_flag("--overwrite", args.options.overwrite,
                "Replace the dataset already in the output folder");
  cmd->add_flag("-q,--quiet", args.options.quiet, "No progress on stderr");
  cmd->footer(
      "Examples:\n"
      "  simcap render scenes/studio4.yaml -o out/studio4 --frames 60\n"
      "  simcap render scenes/studio4.yaml -o out/small --set 'rig.resolution=[320,240]'\n"
      "  simcap render scenes/studio4.yaml -o out/studio4 --resume\n"
      "  simcap render scenes/studio4.yaml -o out/two --cameras cam00,cam02\n"
      "Writes scene.yaml, meta.json, calibration/, background/, camNN/{rgb,depth,mask,parts}/,\n"
      "parts.json, gt/{joints3d,joints2d,angles,joints3d_h36m17}.csv, gt/keypoints_coco.json\n"
      "and, for a gesture corpus, gt/gestures.csv (layout: docs/ARCHITECTURE.md).");
  cmd->callback([&action] { action = [] { return run_render(args); }; });
}

}  // namespace simcap::cli
