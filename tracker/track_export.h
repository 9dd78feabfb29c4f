// A track's motion in the formats animation tools read (`simcap track --export`): BVH, X3D
// H-Anim (HAnimMotion) and MPEG-4 BAP on simcap's humanoid sized to the track, from any
// tracker's joints3d.csv.
#pragma once

#include <filesystem>
#include <vector>

#include "core/name_table.h"

namespace simcap::tracker {

enum class MotionExport { bvh, x3d, bap };
inline constexpr NameTable<MotionExport, 3> kMotionExports{
    {{"bvh", MotionExport::bvh}, {"x3d", MotionExport::x3d}, {"bap", MotionExport::bap}}};

// Reads TRACK/joints3d.csv and writes TRACK/motion.bvh, motion.x3d and/or motion.bap: the poses of
// models/pose_from_joints.h (humanoid_for_track, motion_from_track) at `fps`, one frame per
// dataset frame from the track's first to its last (frames without every HE15 joint hold the
// previous pose). BVH: simcap's skeleton in metres (models/bvh_export.h); X3D: the humanoid with
// its skin and an HAnimMotion (models/x3d_export.h); BAP: MPEG-4 body animation parameters
// (models/mpeg4_bap.h) of those poses read as the monocular body's angles (gomez/bap_export.h).
// A file the tracker wrote itself (monocular: motion.bvh and motion.bap of its own body's
// angles) is kept. Returns the number of held frames.
int export_track_motion(const std::filesystem::path& track, double fps,
                        const std::vector<MotionExport>& formats);

}  // namespace simcap::tracker
