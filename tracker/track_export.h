// A track's motion in the formats animation tools read (`simcap track --export`): BVH and X3D
// H-Anim (HAnimMotion) on simcap's humanoid sized to the track, from any tracker's joints3d.csv.
#pragma once

#include <filesystem>
#include <vector>

#include "core/name_table.h"

namespace simcap::tracker {

enum class MotionExport { bvh, x3d };
inline constexpr NameTable<MotionExport, 2> kMotionExports{
    {{"bvh", MotionExport::bvh}, {"x3d", MotionExport::x3d}}};

// Reads TRACK/joints3d.csv and writes TRACK/motion.bvh and/or TRACK/motion.x3d: the poses of
// models/pose_from_joints.h (humanoid_for_track, motion_from_track) at `fps`, one frame per
// dataset frame from the track's first to its last (frames without every HE15 joint hold the
// previous pose). BVH: simcap's skeleton in metres (models/bvh_export.h); X3D: the humanoid with
// its skin and an HAnimMotion (models/x3d_export.h). Returns the number of held frames.
int export_track_motion(const std::filesystem::path& track, double fps,
                        const std::vector<MotionExport>& formats);

}  // namespace simcap::tracker
