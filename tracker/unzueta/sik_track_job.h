// `simcap track --method sik`: SIK on a dataset's ground-truth end-effectors (optionally noisy),
// writing the HE15 joints of the solved humanoid to TRACK/joints3d.csv.
#pragma once

#include <cstdint>
#include <filesystem>

#include "core/joint_track.h"
#include "models/skeleton.h"
#include "tracker/common/track_summary.h"

namespace simcap {

struct SikTrackOptions {
  double noise_sigma_m = 0.0;
  std::uint64_t seed = 1;
  bool quiet = false;
};

// Reads DATASET/gt/joints3d.csv; needs humanoid_root, skullbase (or skull_tip), l/r_radiocarpal
// and l/r_talocrural. Solves every frame in order with SIK (limits and collisions on, floor
// y = 0) on build_humanoid() refitted to the truth's segment lengths (sik_humanoid_for_track),
// after adding N(0, noise_sigma_m^2) to each coordinate of each end-effector (std::mt19937_64
// seeded with `seed`, so a seed gives the same output). Writes OUT/joints3d.csv (HE15 joints) and
// OUT/diagnostics/sik_humanoid.csv (the fitted humanoid's neutral joint centres).
TrackSummary track_dataset_sik(const std::filesystem::path& dataset,
                               const std::filesystem::path& out, const SikTrackOptions& options);

// build_humanoid() at the truth's height (the median ratio of tracked bone lengths to the
// canonical ones), then the bones between each tracked joint and its nearest tracked ancestor
// scaled to their mean distance in `truth` (a bone shared by two such paths, e.g. the spine below
// vc7 and a shoulder when only HE15 is tracked, takes the first path's factor).
Skeleton sik_humanoid_for_track(const JointTrack& truth);

}  // namespace simcap
