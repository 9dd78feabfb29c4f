// A small dataset written directly by the tests (calibration, gt/joints3d.csv, gt/joints2d.csv,
// grey RGB frames) and tracks derived from its truth, so that validate is tested without the
// renderer. VisibilityLabel labels are assigned by rule, so that the expected groups are known.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joint_track.h"

namespace simcap::testing {

struct SyntheticDataset {
  std::filesystem::path root;
  std::vector<Camera> cameras;
  JointTrack truth;
};

// Writes `frames` frames starting at `first_frame` of the neutral humanoid (HE15 joints plus
// skull_tip) walking along +X, seen by a 3-camera ring rig of 160x120 images. In joints2d.csv
// l_elbow is self_occluded in cam01, r_knee scene_occluded in cam02 and everything else visible.
SyntheticDataset write_synthetic_dataset(const std::filesystem::path& root, int frames = 12,
                                         int first_frame = 0);

// Writes TRACK/joints3d.csv: the truth with every position passed through `f(frame, joint, p)`.
void write_track(
    const std::filesystem::path& track_dir, const JointTrack& truth,
    const std::function<Eigen::Vector3d(int, const std::string&, const Eigen::Vector3d&)>& f);

}  // namespace simcap::testing
