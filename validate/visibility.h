// Which cameras see each joint, from a dataset's gt/joints2d.csv: per frame, joint and camera
// the renderer's visibility label (visible, self_occluded, scene_occluded, out_of_frame).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simcap {

enum class VisibilityLabel : std::uint8_t {
  visible,
  self_occluded,
  scene_occluded,
  out_of_frame,
  missing
};

// The label as written in joints2d.csv ("visible", ...); "missing" for a row the table lacks.
std::string_view visibility_label_name(VisibilityLabel v);
// The label a joints2d.csv cell names; empty for any other text (and for "missing").
std::optional<VisibilityLabel> visibility_label_of(std::string_view name);

// The columns of gt/joints2d.csv (ARCHITECTURE.md, dataset layout).
inline const std::vector<std::string> kJoints2dColumns = {"frame", "camera", "joint",     "u",
                                                          "v",     "depth",  "visibility"};

struct VisibilityTable {
  std::vector<std::string> cameras;  // order of the last index of `status`
  std::vector<std::string> joints;   // order of first appearance
  std::vector<int> frames;           // ascending
  // status[f][j][c]: joint j at frames[f] seen from cameras[c]; `missing` where there is no row.
  std::vector<std::vector<std::vector<VisibilityLabel>>> status;

  int frame_index(int frame) const;                // -1 when absent
  int joint_index(const std::string& name) const;  // -1 when absent
};

// Reads joints2d.csv. `cameras` are the dataset's camera names (from its calibration); a row
// naming another camera, an unknown label or a repeated row is an Error naming file:line.
VisibilityTable read_visibility_table(const std::filesystem::path& path,
                                      const std::vector<std::string>& cameras);

}  // namespace simcap
