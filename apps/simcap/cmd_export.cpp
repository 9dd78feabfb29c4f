// simcap export DATASET -o scene.glb: a rendered dataset as one glTF file (room, cameras,
// animated bodies) to look at in Blender or a web viewer.
#include <cstdio>
#include <memory>

#include "apps/simcap/commands.h"
#include "sim/dataset_gltf.h"

namespace simcap::cli {

void add_export(CLI::App& app, Action& action) {
  struct Options {
    std::string dataset, output;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "export", "Write a dataset as one binary glTF: room, occluders, cameras, animated bodies");
  cmd->add_option("dataset", o->dataset, "Dataset folder (simcap render's output)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("-o,--output", o->output, "glTF file to write (.glb)")->required();
  cmd->footer(
      "The cameras are glTF cameras (the exact calibration is in each camera node's extras);\n"
      "each actor's skeleton moves through the ground truth, one animation key per frame.\n"
      "Examples:\n"
      "  simcap export out/studio4 -o studio4.glb\n"
      "  blender --python-expr \"import bpy; bpy.ops.import_scene.gltf(filepath='studio4.glb')\"");
  cmd->callback([&action, o] {
    action = [o] {
      const DatasetGltfSummary s = export_dataset_gltf(o->dataset, o->output);
      std::fprintf(stderr, "wrote %s: %d cameras, %d actors, %d frames\n", o->output.c_str(),
                   s.cameras, s.actors, s.frames);
      return 0;
    };
  });
}

}  // namespace simcap::cli
