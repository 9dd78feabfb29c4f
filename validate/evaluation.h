// Scores one tracked sequence against its ground truth: every metric simcap reports (MPJPE,
// PA-MPJPE, PCK, Moschini's per-point RMSE, Balan's wrist/elbow error, joint-angle RMSE, errors by
// visibility, tracking failures), computed from frame-aligned inputs the loader has checked.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "validate/metrics.h"

namespace simcap {

// The worst occlusion of a joint over the cameras in one frame.
enum class Occlusion { none, self, scene };

struct JointSight {
  int visible_cameras = 0;                // cameras labelling the joint `visible`
  Occlusion occlusion = Occlusion::none;  // scene if any camera says scene_occluded, else self if
                                          // any says self_occluded
};

struct EvaluationInput {
  std::vector<std::string> joints;                // evaluated joints, column order of the matrices
  std::vector<int> frames;                        // ascending
  std::vector<Eigen::Matrix3Xd> truth, estimate;  // per frame, metres
  // VisibilityLabel per frame and joint ([f][j]); empty when not known.
  int camera_count = 0;
  std::vector<std::vector<JointSight>> views;
  // The camera's centre (world, metres) when the dataset has one camera: errors are then split
  // along and across its rays (depth ambiguity).
  std::optional<Eigen::Vector3d> camera_centre;
  // Joint rotations both sides have ([f][k]); empty when the tracker wrote no angles.
  std::vector<std::string> angle_joints;
  std::vector<std::vector<Eigen::Quaterniond>> truth_rotations, estimate_rotations;
};

struct EvaluationOptions {
  double failure_threshold_mm = 100.0;
  std::vector<double> pck_thresholds_mm = {50.0, 100.0, 150.0};
};

// One joint's error split by the single camera's ray through its true position: the component
// along the ray (depth, what one view cannot see) and the one across it (the image plane).
struct RaySplit {
  double along_mm = 0, across_mm = 0;  // means of the components' magnitudes
};

struct JointScore {
  std::string joint;
  double mpjpe_mm = 0, pa_mpjpe_mm = 0, rmse_mm = 0, max_mm = 0;
  std::optional<RaySplit> ray;  // with EvaluationInput::camera_centre
};

struct FrameScore {
  int frame = 0;
  double mpjpe_mm = 0, pa_mpjpe_mm = 0;
  std::optional<RaySplit> ray;  // the frame's joints, with EvaluationInput::camera_centre
};

struct PckScore {
  double threshold_mm = 0;
  double fraction = 0;  // of all joint-frames
};

struct AngleScore {
  std::string joint;
  double rmse_rad = 0, mean_rad = 0, max_rad = 0;
};

// Mean 3D error of the joint-frames that fall into one visibility group.
struct VisibilityGroup {
  std::string label;         // "k cameras" or an Occlusion name
  int visible_cameras = -1;  // the k of "seen by k cameras"; -1 for occlusion groups
  long count = 0;            // joint-frames in the group
  double mpjpe_mm = 0;       // 0 when count is 0
};

struct FailureSummary {
  double threshold_mm = 0;
  long failed_frames = 0;
  double failed_fraction = 0;
  std::vector<FailureEpisode> episodes;
  double mean_recovery_frames = 0;  // over recovered episodes; 0 when none
  int max_recovery_frames = 0;
};

struct Evaluation {
  std::vector<std::string> joints;
  std::vector<int> frames;
  double mpjpe_mm = 0, pa_mpjpe_mm = 0;
  std::vector<PckScore> pck;
  double rmse_mean_mm = 0;      // mean over joints of the per-point RMSE (Moschini Table 7.2)
  double wrists_elbows_mm = 0;  // mean error over l/r elbow and wrist (Gomez, after Balan)
  std::optional<RaySplit> ray;  // over all joint-frames, with EvaluationInput::camera_centre
  std::vector<JointScore> per_joint;
  std::vector<FrameScore> per_frame;
  std::vector<AngleScore> angles;  // empty when no angles were compared
  double angle_rmse_mean_rad = 0;
  int camera_count = 0;
  std::vector<VisibilityGroup> by_visible_cameras;  // k = 0 .. camera_count; empty if unknown
  std::vector<VisibilityGroup> by_occlusion;        // none, self, scene; empty if unknown
  FailureSummary failures;
};

// Joints that the wrist/elbow error averages over.
const std::vector<std::string>& wrist_elbow_joints();

// Throws Error when the input is inconsistent (sizes) or lacks the wrist and elbow joints.
Evaluation evaluate(const EvaluationInput& input, const EvaluationOptions& options = {});

const char* occlusion_name(Occlusion o);

}  // namespace simcap
