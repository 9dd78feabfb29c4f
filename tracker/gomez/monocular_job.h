// `simcap track --method monocular`: Gomez Jauregui's tracker over one camera of a dataset.
// Writes TRACK/joints3d.csv (HE15, world frame), TRACK/motion.bap (MPEG-4 BAPs of the body's
// angles), TRACK/motion.bvh (the tracked skeleton and motion) and TRACK/diagnostics/.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "tracker/common/dataset.h"
#include "tracker/common/init_method.h"
#include "tracker/common/silhouettes.h"
#include "tracker/common/track_summary.h"
#include "tracker/gomez/monocular_tracker.h"

namespace simcap::tracker {

struct MonocularOptions {
  gomez::MonocularSettings tracker;
  SilhouetteMethod silhouettes = SilhouetteMethod::gt;
  // gt: the body sized and posed from gt/joints3d.csv's first frame; automatic: an upright
  // person facing the camera, sized from the first silhouette (gomez/upright_start.h).
  InitMethod init = InitMethod::gt;
  int camera = 0;  // the dataset's camera to track in
  // Frames whose inspection picture (gomez/inspection.h) goes to diagnostics/inspect/FRAME.png.
  std::vector<int> inspect;
  // Every frame's search starts from its ground-truth pose (gt/joints3d.csv fitted by the body).
  bool oracle = false;
  int max_frames = -1;  // the first frames only; < 0: every frame
  bool quiet = false;
};

// Tracks the dataset's frames in one camera and writes OUT/joints3d.csv, OUT/motion.bap,
// OUT/motion.bvh and OUT/diagnostics/.
TrackSummary track_monocular(const std::filesystem::path& dataset, const std::filesystem::path& out,
                             const MonocularOptions& options);

// The tracker over the dataset's frames (`max_frames` < 0: all) without files; `sink` sees every
// frame in order. Used by track_monocular and by `simcap bench track`.
using MonocularSink =
    std::function<void(int frame, const gomez::TrackedFrame&, const gomez::MonocularTracker&)>;
TrackSummary run_monocular(const Dataset& dataset, const MonocularOptions& options, int max_frames,
                           const MonocularSink& sink);

}  // namespace simcap::tracker
