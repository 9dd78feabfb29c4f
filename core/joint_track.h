// 3D positions of named joints over frames: the `frame,joint,x,y,z` table that the renderer
// writes as ground truth (gt/joints3d.csv) and every tracker writes as its result.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace simcap {

struct JointTrack {
  std::vector<std::string> joints;  // column order
  std::vector<int> frames;          // ascending frame numbers
  // positions[f][j]: joint j at frames[f]; NaN where the table has no row for it.
  std::vector<std::vector<Eigen::Vector3d>> positions;

  int joint_index(const std::string& name) const;  // -1 when absent
  // Appends a frame; `p` is in the order of `joints`.
  void add_frame(int frame, std::vector<Eigen::Vector3d> p);
};

inline const std::vector<std::string> kJoints3dColumns = {"frame", "joint", "x", "y", "z"};

// Writes frame,joint,x,y,z with 7 decimals (0.1 micrometre), skipping NaN positions.
void write_joint_track(const std::filesystem::path& path, const JointTrack& track);
// Reads the table; joints in order of first appearance. Errors name file:line and column.
JointTrack read_joint_track(const std::filesystem::path& path);

}  // namespace simcap
