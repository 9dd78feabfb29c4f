// `simcap render` as a library call: loads a scene, renders every frame of every camera and
// writes the complete dataset (images, ground truth, calibration, meta.json). `simcap loop` and
// `simcap demo` call it too.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace simcap {

struct RenderOptions {
  int frames = -1;  // > 0: render this many frames instead of the scene's
  // A BVH file replacing the first actor's motion, or an AMC file with `motion_asf` its ASF.
  std::filesystem::path motion_override;
  std::filesystem::path motion_asf;
  std::optional<std::uint64_t> seed;  // replaces the scene's render seed
  // Names of the rig's cameras to render (kept in rig order, with their names; the dataset then
  // holds only these); empty: all. A camera's images do not depend on which others are rendered.
  std::vector<std::string> cameras;
  // Continue a render in `out_dir`: frames whose files all exist are not rendered again (their
  // ground truth is recomputed, which is cheap). The scene must be the one rendered there.
  bool resume = false;
  // Replace a dataset already in `out_dir` (its simcap files and folders are removed first).
  bool overwrite = false;
  // When set: render only the images of dataset frames [first, end) — a chunk of a sequence
  // split across processes. No background plates, no ground-truth tables; meta.json stays
  // "complete": false. A `resume` render of the whole sequence over the chunks' images (linked
  // into one folder) completes it with the bytes of an uninterrupted render.
  struct FrameRange {
    int first = 0, end = 0;
  };
  std::optional<FrameRange> image_frames;
  bool quiet = false;                  // no progress on stderr
  std::vector<std::string> overrides;  // "key.path=value" scene overrides (load_scene)
};

struct RenderSummary {
  int frames = 0;
  int cameras = 0;
  double seconds = 0;  // wall time of the whole job
  // Thread-seconds spent encoding and writing image files (pipelined with rendering, so it
  // overlaps `seconds`; the share of the CPU it took is write_seconds / (seconds * threads)).
  double write_seconds = 0;
  std::filesystem::path dataset;
};

// The scene render_dataset renders with these options (overrides, seed, --motion, --frames and
// --cameras applied), checked as it checks it; throws Error.
Scene load_for_render(const std::filesystem::path& scene_file, const RenderOptions& options);

// Renders `scene_file` into `out_dir`. The folder must not exist or be empty, unless `resume`
// or `overwrite` says what to do with what is there. Everything that can be checked before
// rendering (scene, motion files, textures, meshes, the output folder) is checked before the
// first file is written. Throws Error.
RenderSummary render_dataset(const std::filesystem::path& scene_file,
                             const std::filesystem::path& out_dir, const RenderOptions& options);

}  // namespace simcap
