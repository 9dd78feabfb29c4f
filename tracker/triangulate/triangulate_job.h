// `simcap track --method triangulate`: a 2D detector's keypoints in every camera of a dataset,
// triangulated into H-Anim joints (TRACK/joints3d.csv) with what it chose in TRACK/diagnostics/.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/joint_track.h"
#include "core/name_table.h"
#include "models/detections.h"
#include "tracker/common/dataset.h"
#include "tracker/common/init_method.h"
#include "tracker/common/track_summary.h"
#include "tracker/triangulate/person_association.h"
#include "tracker/triangulate/pose_triangulator.h"

namespace simcap::tracker {

enum class TemporalFilter { none, butterworth, kalman };
inline constexpr NameTable<TemporalFilter, 3> kTemporalFilters{
    {{"none", TemporalFilter::none},
     {"butterworth", TemporalFilter::butterworth},
     {"kalman", TemporalFilter::kalman}}};

struct TriangulateOptions {
  std::filesystem::path detections;        // COCO results JSON, OpenPose folder or CSV
  std::optional<KeypointLayoutId> layout;  // inferred from the file when not given
  PoseTriangulationOptions triangulation;
  AssociationOptions association;
  // Zero-phase low-pass of every keypoint's coordinates over time (butterworth.h) after gaps
  // are filled; on by default: 37% lower MPJPE on every clip of the suite (TRIANGULATE.md).
  TemporalFilter filter = TemporalFilter::butterworth;
  double cutoff_hz = 6.0;  // Pose2Sim's default
  // Every frame's keypoints moved onto the take's median bone lengths (bone_lengths.h) before
  // gaps are filled and the low-pass runs.
  bool bone_lengths = true;
  // gt: the actor is found in the first frame where the ground truth projects; automatic: the
  // most prominent person detected (person_association.h).
  InitMethod init = InitMethod::gt;
  std::string actor;
  int max_frames = -1;  // the first frames only; < 0: every frame
  bool quiet = false;
};

struct TriangulateStages {
  double read_s = 0, associate_s = 0, triangulate_s = 0, smooth_s = 0;
};

struct TriangulationResult {
  JointTrack track;       // H-Anim joints (hanim_joints.h)
  std::string people;     // diagnostics/people.csv
  std::string keypoints;  // diagnostics/keypoints.csv
  std::string swaps;      // diagnostics/swaps.csv
  int frames = 0, swaps_repaired = 0, views_excluded = 0, keypoints_missing = 0;
  // Keypoints no two views saw in any frame, placed from the reference body (unseen_keypoints.h).
  std::vector<std::string> unseen;
  TriangulateStages stages;
};

// The whole method without files (the bench times its stages).
TriangulationResult run_triangulation(const Dataset& dataset, const TriangulateOptions& options);

// Writes OUT/joints3d.csv and OUT/diagnostics/{people,keypoints,swaps}.csv. Missing or
// unreadable detections are an Error before anything is written.
TrackSummary track_triangulate(const std::filesystem::path& dataset,
                               const std::filesystem::path& out, const TriangulateOptions& options);

}  // namespace simcap::tracker
