// `simcap track --method moschini`: Moschini's pipeline over a dataset, writing TRACK/joints3d.csv
// (HE15, H-Anim names) plus TRACK/diagnostics/; and the same run without files for benchmarks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <vector>

#include "core/name_table.h"
#include "tracker/common/dataset.h"
#include "tracker/common/init_method.h"
#include "tracker/common/track_summary.h"
#include "tracker/moschini/moschini_tracker.h"
#include "tracker/moschini/perception.h"

namespace simcap::tracker {

enum class MotionFilter { none, ekf };
inline constexpr NameTable<MotionFilter, 2> kMotionFilters{
    {{"none", MotionFilter::none}, {"ekf", MotionFilter::ekf}}};

struct MoschiniOptions {
  SilhouetteMethod silhouettes = SilhouetteMethod::gt;
  InitMethod init = InitMethod::gt;
  // moschini (Table 5.1, 23-parameter EKF) or urdf (adds hip twists, a spine joint, wrists and
  // ankles).
  JointSet joints = JointSet::urdf;
  double voxel_m = 0.02;
  // Learn the parts' colours on the first frame and let each silhouette ray meet only the parts
  // its colour may show.
  bool appearance = true;
  // none: the fitted pose is the estimate and the next frame's start; ekf: Moschini's EKF
  // smooths it (with its random-walk model it lags a moving body, which costs 1-18 mm on
  // simcap's datasets, tracker/moschini/MOSCHINI.md).
  MotionFilter filter = MotionFilter::none;
  // Off: each frame's fit starts from the previous pose; on: Moschini's hierarchical ICP
  // traversal is tried too and the lower refinement cost wins.
  bool traversal = false;
  // Learn where scene objects hide the person from a camera, which then abstains there from
  // carving the hull and from the outline cues (occlusion_map.h).
  bool occlusion = true;
  // Every frame starts from its ground-truth pose instead of the previous estimate (needs
  // gt/joints3d.csv): what is left is the error of the body model and the cues, without the
  // search's.
  bool oracle = false;
  // URDF joint limits of the urdf joint set (read_urdf_limits; `simcap track --limits`). Empty:
  // the dataset's scene.yaml actors[0].limits when it names one, else the shipped
  // humanoid_limits.urdf. An explicit file with the moschini joint set is an error (that set
  // keeps Table 5.1).
  std::filesystem::path limits;
  // Frames to lay open in TRACK/diagnostics/inspect/FRAME/ (inspection.h).
  std::vector<int> inspect;
  int max_frames = -1;  // the first frames only; < 0: every frame
  bool quiet = false;
  // The person to track (tracker/common/dataset.h); empty: the first actor.
  std::string actor;
};

// Tracks every frame of `dataset` and writes OUT/joints3d.csv (HE15, H-Anim names) and
// OUT/diagnostics/.
TrackSummary track_moschini(const std::filesystem::path& dataset, const std::filesystem::path& out,
                            const MoschiniOptions& options);

// Moschini's pipeline without files: perception runs on several frames at once, tracking runs
// in frame order, and `sink` sees every frame in order (with the dataset it came from).
// `max_frames` < 0 means all. Used by track_dataset and by `simcap bench track`.
using MoschiniSink = std::function<void(const Dataset&, const Observation&, const TrackStep&,
                                        const MoschiniTracker&)>;
TrackSummary run_moschini(const std::filesystem::path& dataset, const MoschiniOptions& options,
                          int max_frames, const MoschiniSink& sink);

}  // namespace simcap::tracker
