// Joint rotations over frames: the `frame,joint,qw,qx,qy,qz` table of a dataset's gt/angles.csv
// (each joint's rotation relative to the neutral pose, in its parent's frame) and of a tracker's
// optional angles.csv in the same schema.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <string>
#include <vector>

namespace simcap {

inline const std::vector<std::string> kAnglesColumns = {"frame", "joint", "qw", "qx", "qy", "qz"};

struct AngleTrack {
  std::vector<std::string> joints;  // order of first appearance
  std::vector<int> frames;          // ascending
  // rotations[f][j]: unit quaternion; all-NaN coefficients where the table has no row.
  std::vector<std::vector<Eigen::Quaterniond>> rotations;

  int joint_index(const std::string& name) const;  // -1 when absent
  // Appends a frame; `q` is in the order of `joints`.
  void add_frame(int frame, std::vector<Eigen::Quaterniond> q);
};

// Writes frame,joint,qw,qx,qy,qz with 9 decimals, as the renderer writes gt/angles.csv.
void write_angle_track(const std::filesystem::path& path, const AngleTrack& track);
// Reads the table; a quaternion whose norm is not 1 within 1e-3 is an Error naming file:line.
AngleTrack read_angle_track(const std::filesystem::path& path);

}  // namespace simcap
