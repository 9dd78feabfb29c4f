// What `simcap track` asks of a tracker: which family runs, with what first pose, and each
// family's own typed options (the command line fills them; the libraries never parse text).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/name_table.h"
#include "tracker/common/init_method.h"
#include "tracker/common/silhouettes.h"
#include "tracker/gomez/monocular_job.h"
#include "tracker/moschini/moschini_job.h"
#include "tracker/track_export.h"
#include "tracker/triangulate/triangulate_job.h"
#include "tracker/unzueta/sik_track_job.h"

namespace simcap::tracker {

// automatic: the family that suits the dataset's cameras (registry.h, resolve_method).
enum class TrackMethod { automatic, moschini, sik, monocular, triangulate };
inline constexpr NameTable<TrackMethod, 5> kTrackMethods{
    {{"auto", TrackMethod::automatic},
     {"moschini", TrackMethod::moschini},
     {"sik", TrackMethod::sik},
     {"monocular", TrackMethod::monocular},
     {"triangulate", TrackMethod::triangulate}}};

struct TrackOptions {
  TrackMethod method = TrackMethod::automatic;
  // Options every family shares; the registry hands them to the family that runs.
  InitMethod init = InitMethod::gt;
  // The person to track, by scene.yaml name; empty: the first actor. The track records it in
  // TRACK/actor.txt when the dataset has several actors (core/dataset_actors.h).
  std::string actor;
  SilhouetteMethod silhouettes =
      SilhouetteMethod::gt;  // moschini, monocular; sik from pixels (pelvis)
  std::uint64_t seed = 1;    // sik's noise, monocular's particles
  std::vector<int> inspect;  // frames to lay open in diagnostics/inspect/ (moschini, monocular)
  // Every frame starts from its ground-truth pose (moschini, monocular): a diagnostic of the
  // error the body model and the cues leave without the search's.
  bool oracle = false;
  int max_frames = -1;  // the first frames only; < 0: every frame
  bool quiet = false;
  // Formats the track's motion is also written in (TRACK/motion.bvh, motion.x3d).
  std::vector<MotionExport> exports;
  MoschiniOptions moschini;
  SikTrackOptions sik;
  MonocularOptions monocular;
  TriangulateOptions triangulate;
};

}  // namespace simcap::tracker
