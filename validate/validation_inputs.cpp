#include "validate/validation_inputs.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>

#include "core/angle_track.h"
#include "core/calibration.h"
#include "core/dataset_actors.h"
#include "core/error.h"
#include "core/joint_track.h"
#include "core/loop_folder.h"
#include "core/track_source.h"
#include "models/humanoid.h"
#include "validate/visibility.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

std::string describe_frames(const std::vector<int>& frames) {
  if (frames.empty()) return "no frames";
  return std::to_string(frames.size()) + " frames (" + std::to_string(frames.front()) + " to " +
         std::to_string(frames.back()) + ")";
}

void require_file(const fs::path& file, const std::string& what) {
  if (!fs::is_regular_file(file)) throw_input_error(file, 0, "", "missing; expected " + what);
}

void check_folders(const fs::path& dataset, const fs::path& track) {
  if (!fs::is_directory(dataset)) {
    throw_input_error(dataset, 0, "", "not a folder; expected a dataset written by simcap render");
  }
  if (!fs::is_directory(track)) {
    throw_input_error(track, 0, "", "not a folder; expected a track written by simcap track");
  }
  refuse_loop_folder(dataset, "dataset");
  refuse_loop_folder(track, "track");
  const fs::path gt = dataset / "gt" / "joints3d.csv";
  if (!fs::is_regular_file(gt) && fs::is_regular_file(dataset / "joints3d.csv") &&
      fs::is_regular_file(track / "gt" / "joints3d.csv")) {
    throw_input_error(dataset, 0, "",
                      "this is a track and the second argument is a dataset; the order is "
                      "DATASET TRACK");
  }
  require_file(gt, "the ground-truth 3D joints of a dataset written by simcap render");
  const fs::path tracked = track / "joints3d.csv";
  if (!fs::is_regular_file(tracked) && fs::is_regular_file(track / "gt" / "joints3d.csv")) {
    throw_input_error(track, 0, "",
                      "this is a dataset, not a track; expected a folder written by simcap track");
  }
  require_file(tracked, "the tracker's 3D joints (frame,joint,x,y,z) written by simcap track");
  require_file(dataset / "gt" / "joints2d.csv",
               "the per-camera 2D joints and visibility of the dataset");
  require_file(dataset / "calibration" / "opencv.yaml", "the dataset's camera calibration");
}

// Joints both sides have: HE15 (required on both) first, then the rest in ground-truth order.
std::vector<std::string> evaluated_joints(const JointTrack& truth, const fs::path& truth_file,
                                          const JointTrack& estimate, const fs::path& est_file) {
  for (const auto& [t, file] : {std::pair{&truth, truth_file}, std::pair{&estimate, est_file}}) {
    std::string missing;
    for (const auto& name : he15_joints()) {
      if (t->joint_index(name) < 0) missing += (missing.empty() ? "" : ", ") + name;
    }
    if (!missing.empty()) {
      throw_input_error(file, 0, "joint",
                        "missing " + missing + "; expected at least the HE15 joints");
    }
  }
  std::vector<std::string> joints = he15_joints();
  for (const auto& name : truth.joints) {
    if (estimate.joint_index(name) >= 0 &&
        std::find(joints.begin(), joints.end(), name) == joints.end()) {
      joints.push_back(name);
    }
  }
  return joints;
}

// The track's frames: the ground truth's, or their first N (`simcap track --frames N`).
void check_scored_frames(const JointTrack& truth, const fs::path& truth_file,
                         const std::vector<int>& frames, const fs::path& file) {
  if (frames.size() <= truth.frames.size() &&
      std::equal(frames.begin(), frames.end(), truth.frames.begin())) {
    return;
  }
  std::string detail;
  for (int f : frames) {
    if (!std::binary_search(truth.frames.begin(), truth.frames.end(), f)) {
      detail = "frame " + std::to_string(f) + " is not in the ground truth";
      break;
    }
  }
  if (detail.empty()) {
    for (int f : truth.frames) {
      if (!std::binary_search(frames.begin(), frames.end(), f)) {
        detail = "no rows for frame " + std::to_string(f);
        break;
      }
    }
  }
  throw_input_error(file, 0, "frame",
                    "has " + describe_frames(frames) + " but " + truth_file.string() + " has " +
                        describe_frames(truth.frames) +
                        "; expected the same frames, or their first N as `simcap track --frames N` "
                        "writes (" +
                        detail + ")");
}

Eigen::Matrix3Xd frame_matrix(const JointTrack& t, size_t f, const std::vector<std::string>& joints,
                              const fs::path& file) {
  Eigen::Matrix3Xd m(3, joints.size());
  for (size_t j = 0; j < joints.size(); ++j) {
    const Eigen::Vector3d& p = t.positions[f][t.joint_index(joints[j])];
    if (!p.allFinite()) {
      throw_input_error(file, 0, "joint",
                        "frame " + std::to_string(t.frames[f]) + " has no row for joint '" +
                            joints[j] + "'; expected every joint in every frame");
    }
    m.col(static_cast<Eigen::Index>(j)) = p;
  }
  return m;
}

// `prefix`: how the table names the tracked actor's joints (core/dataset_actors.h).
void add_visibility(const fs::path& file, const std::vector<Camera>& cameras,
                    const std::string& prefix, EvaluationInput& in) {
  std::vector<std::string> names;
  for (const auto& c : cameras) names.push_back(c.name);
  const VisibilityTable table = read_visibility_table(file, names);
  in.camera_count = static_cast<int>(cameras.size());
  for (int frame : in.frames) {
    const int f = table.frame_index(frame);
    if (f < 0) {
      throw_input_error(file, 0, "frame",
                        "no rows for frame " + std::to_string(frame) +
                            "; expected the frames of gt/joints3d.csv");
    }
    auto& views = in.views.emplace_back();
    for (const auto& joint : in.joints) {
      const int j = table.joint_index(prefix + joint);
      if (j < 0) {
        throw_input_error(file, 0, "joint", "no rows for joint '" + prefix + joint + "'");
      }
      JointSight v;
      for (size_t c = 0; c < cameras.size(); ++c) {
        switch (table.status[f][j][c]) {
          case VisibilityLabel::visible:
            ++v.visible_cameras;
            break;
          case VisibilityLabel::self_occluded:
            if (v.occlusion == Occlusion::none) v.occlusion = Occlusion::self;
            break;
          case VisibilityLabel::scene_occluded:
            v.occlusion = Occlusion::scene;
            break;
          case VisibilityLabel::out_of_frame:
            break;
          case VisibilityLabel::missing:
            throw_input_error(file, 0, "camera",
                              "no row for joint '" + prefix + joint + "' in camera " + names[c] +
                                  " at frame " + std::to_string(frame));
        }
      }
      views.push_back(v);
    }
  }
}

void add_angles(const fs::path& truth_file, const fs::path& est_file, const std::string& prefix,
                EvaluationInput& in) {
  require_file(truth_file,
               "the ground-truth joint rotations to compare " + est_file.string() + " with");
  const AngleTrack truth = read_angle_track(truth_file);
  const AngleTrack est = read_angle_track(est_file);
  for (const auto& name : est.joints) {
    if (truth.joint_index(prefix + name) >= 0) in.angle_joints.push_back(name);
  }
  if (in.angle_joints.empty()) {
    throw_input_error(est_file, 0, "joint", "no joint in common with " + truth_file.string());
  }
  if (est.frames != in.frames) {
    throw_input_error(est_file, 0, "frame",
                      "has " + describe_frames(est.frames) + "; expected the " +
                          describe_frames(in.frames) + " of the tracked joints3d.csv");
  }
  for (size_t f = 0; f < in.frames.size(); ++f) {
    const int frame = in.frames[f];
    const auto tf = std::lower_bound(truth.frames.begin(), truth.frames.end(), frame);
    if (tf == truth.frames.end() || *tf != frame) {
      throw_input_error(truth_file, 0, "frame", "no rows for frame " + std::to_string(frame));
    }
    const auto& tr = truth.rotations[tf - truth.frames.begin()];
    const auto& er = est.rotations[f];
    auto& t_out = in.truth_rotations.emplace_back();
    auto& e_out = in.estimate_rotations.emplace_back();
    for (const auto& name : in.angle_joints) {
      const Eigen::Quaterniond& qt = tr[truth.joint_index(prefix + name)];
      const Eigen::Quaterniond& qe = er[est.joint_index(name)];
      for (const auto& [q, file] : {std::pair{&qt, truth_file}, std::pair{&qe, est_file}}) {
        if (!q->coeffs().allFinite()) {
          throw_input_error(
              file, 0, "joint",
              "frame " + std::to_string(frame) + " has no row for joint '" + name + "'");
        }
      }
      t_out.push_back(qt);
      e_out.push_back(qe);
    }
  }
}

double scene_fps(const fs::path& scene_file) {
  if (!fs::is_regular_file(scene_file)) return 30.0;
  try {
    const YAML::Node fps = YAML::LoadFile(scene_file.string())["render"]["fps"];
    return fps ? fps.as<double>() : 30.0;
  } catch (const YAML::Exception& e) {
    throw_input_error(scene_file, e.mark.line + 1, "render.fps", e.what());
  }
}

}  // namespace

ValidationInputs load_validation_inputs(const fs::path& dataset, const fs::path& track) {
  check_folders(dataset, track);
  check_track_source(dataset, track);
  ValidationInputs out;
  out.dataset = dataset;
  out.track = track;
  out.cameras = read_opencv_calibration(dataset / "calibration" / "opencv.yaml");
  out.fps = scene_fps(dataset / "scene.yaml");

  const fs::path truth_file = dataset / "gt" / "joints3d.csv";
  const fs::path est_file = track / "joints3d.csv";
  // The tracked actor (TRACK/actor.txt; the first without it), under its own joint names.
  const std::vector<std::string> actors = read_dataset_actors(dataset);
  const int actor =
      find_actor(actors, read_track_actor(track), (track / kTrackActorFile).string() + ": actor");
  const std::string prefix = actor_joint_prefix(actors, actor);
  const JointTrack truth = actor_joints(read_joint_track(truth_file), actors, actor);
  const JointTrack est = read_joint_track(est_file);
  if (truth.frames.empty()) throw_input_error(truth_file, 0, "", "no rows; expected joints");
  if (est.frames.empty()) throw_input_error(est_file, 0, "", "no rows; expected joints");

  EvaluationInput& in = out.evaluation;
  in.joints = evaluated_joints(truth, truth_file, est, est_file);
  check_scored_frames(truth, truth_file, est.frames, est_file);
  in.frames = est.frames;
  for (size_t f = 0; f < in.frames.size(); ++f) {
    in.truth.push_back(frame_matrix(truth, f, in.joints, truth_file));
    in.estimate.push_back(frame_matrix(est, f, in.joints, est_file));
  }
  add_visibility(dataset / "gt" / "joints2d.csv", out.cameras, prefix, in);
  if (out.cameras.size() == 1) in.camera_centre = out.cameras.front().centre();
  if (fs::exists(track / "angles.csv")) {
    add_angles(dataset / "gt" / "angles.csv", track / "angles.csv", prefix, in);
  }
  return out;
}

}  // namespace simcap
