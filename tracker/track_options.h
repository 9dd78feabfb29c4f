// What `simcap track` asks of a tracker: which family runs, with what first pose, and each
// family's own typed options (the command line fills them; the libraries never parse text).
#pragma once

#include "core/name_table.h"
#include "tracker/common/init_method.h"
#include "tracker/moschini/moschini_job.h"
#include "tracker/track_export.h"
#include "tracker/unzueta/sik_track_job.h"

namespace simcap::tracker {

enum class TrackMethod { moschini, sik };
inline constexpr NameTable<TrackMethod, 2> kTrackMethods{
    {{"moschini", TrackMethod::moschini}, {"sik", TrackMethod::sik}}};

struct TrackOptions {
  TrackMethod method = TrackMethod::moschini;
  // Options every family shares; the registry hands them to the family that runs.
  InitMethod init = InitMethod::gt;
  SilhouetteMethod silhouettes = SilhouetteMethod::gt;  // moschini; sik from pixels (pelvis)
  bool quiet = false;
  // Formats the track's motion is also written in (TRACK/motion.bvh, motion.x3d).
  std::vector<MotionExport> exports;
  MoschiniOptions moschini;
  SikTrackOptions sik;
};

}  // namespace simcap::tracker
