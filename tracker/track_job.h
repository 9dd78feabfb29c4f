// `simcap track`: runs a tracker over a dataset and writes TRACK/joints3d.csv (HE15, H-Anim
// names) plus TRACK/diagnostics/. Moschini's pipeline is here; --method sik calls SIK's back-end
// (tracker/sik_track_job.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "tracker/dataset.h"
#include "tracker/moschini_tracker.h"
#include "tracker/perception.h"

namespace simcap {

struct TrackOptions {
  std::string method = "moschini";  // moschini | sik
  std::string silhouettes = "gt";   // gt | bgsub | mog2
  std::string init = "gt";          // gt | auto
  std::string joints = "urdf";      // moschini (Table 5.1, 23-parameter EKF) | urdf (+ hip twists)
  double voxel_m = 0.02;
  // moschini: learn the parts' colours on the first frame and let each silhouette ray meet only
  // the parts its colour may show: "on" | "off".
  std::string appearance = "on";
  // moschini: "none" (the fitted pose is the estimate and the next frame's start) or "ekf"
  // (Moschini's EKF smooths it; with its random-walk model it lags a moving body, which costs
  // 1-18 mm on simcap's datasets, tracker/MOSCHINI.md).
  std::string filter = "none";
  // moschini: "off" (each frame's fit starts from the previous pose) or "on" (Moschini's
  // hierarchical ICP traversal is tried too and the lower refinement cost wins).
  std::string traversal = "off";
  // moschini: every frame starts from its ground-truth pose instead of the previous estimate
  // (needs gt/joints3d.csv): what is left is the error of the body model and the cues, without
  // the search's.
  bool oracle = false;
  // moschini: frames to lay open in TRACK/diagnostics/inspect/FRAME/ (tracker/inspection.h).
  std::vector<int> inspect;
  bool quiet = false;
  double sik_noise_m = 0.0;  // sik: Gaussian noise on the end-effectors, metres
  std::uint64_t seed = 1;    // sik: seed of that noise
};

struct TrackSummary {
  int frames = 0;
  double seconds = 0;
  int reinitializations = 0;
  std::filesystem::path track;
};

TrackSummary track_dataset(const std::filesystem::path& dataset, const std::filesystem::path& out,
                           const TrackOptions& options);

// Moschini's pipeline without files: perception runs on several frames at once, tracking runs
// in frame order, and `sink` sees every frame in order (with the dataset it came from).
// `max_frames` < 0 means all. Used by track_dataset and by `simcap bench track`.
using MoschiniSink =
    std::function<void(const tracker::Dataset&, const tracker::Observation&,
                       const tracker::TrackStep&, const tracker::MoschiniTracker&)>;
TrackSummary run_moschini(const std::filesystem::path& dataset, const TrackOptions& options,
                          int max_frames, const MoschiniSink& sink);

}  // namespace simcap
