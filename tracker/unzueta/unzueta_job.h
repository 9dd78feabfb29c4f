// `simcap track --method sik --effectors depth|mono|multiview`: Unzueta's system from pixels
// (thesis ch. 3-4). Head, hands and feet tracked by CFOF and the pelvis from the silhouette in
// the images, lifted to 3D, turned into SIK's end-effector targets, solved into the H-Anim pose.
#pragma once

#include <filesystem>
#include <functional>

#include "core/effector_track.h"
#include "core/joint_track.h"
#include "tracker/common/track_summary.h"
#include "tracker/unzueta/camera_tracker.h"
#include "tracker/unzueta/sik_track_job.h"

namespace simcap::tracker {

struct UnzuetaFrame {
  int frame = 0;
  // Per effector: the SIK target (its joint) and the part centre it came from, world metres.
  std::array<Eigen::Vector3d, kEffectorCount> target, centre;
  std::vector<Eigen::Vector3d> he15;  // the solved pose's HE15 joints (he15_joints() order)
};

// Runs the pipeline on the dataset's frames in order; `sink` (may be empty) sees each frame with
// the trackers of the cameras used (one for depth and mono, all for multiview) and their
// calibration indices.
using UnzuetaSink = std::function<void(const UnzuetaFrame&, const std::vector<int>& cameras,
                                       const std::vector<CameraTracker>& trackers)>;
// options.effectors must be depth, mono or multiview.
TrackSummary run_unzueta(const std::filesystem::path& dataset, const SikTrackOptions& options,
                         const UnzuetaSink& sink);

// run_unzueta writing OUT/joints3d.csv (HE15), OUT/effectors2d.csv (core/effector_track.h: per
// camera used, frame and effector the pixel of its joint as estimated, the tracked part's pixel
// and the tracker's state), OUT/effectors3d.csv (SIK's targets) and
// OUT/diagnostics/sik_humanoid.csv.
TrackSummary track_dataset_unzueta(const std::filesystem::path& dataset,
                                   const std::filesystem::path& out,
                                   const SikTrackOptions& options);

}  // namespace simcap::tracker
