// Reads the `frame,joint,<value columns>` tables of a dataset (joints3d.csv, angles.csv): one
// row per frame and joint, any order, gathered into frames x joints with a filler for missing rows.
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/csv.h"
#include "core/error.h"
#include "core/limits.h"

namespace simcap {

template <typename Value>
struct JointTable {
  std::vector<std::string> joints;         // order of first appearance
  std::vector<int> frames;                 // ascending
  std::vector<std::vector<Value>> values;  // values[f][j]; `missing` where the table has no row
};

// Index of `name` in `joints`, -1 when absent.
inline int find_joint(const std::vector<std::string>& joints, const std::string& name) {
  const auto it = std::find(joints.begin(), joints.end(), name);
  return it == joints.end() ? -1 : static_cast<int>(it - joints.begin());
}

// The frame number in `column` of the current row: 0 to limits::kMaxFrames - 1.
inline int read_frame_number(const CsvReader& csv, int column) {
  const long frame = csv.integer(column);
  if (frame < 0 || frame >= limits::kMaxFrames) {
    csv.fail(column, "expected a frame number from 0 to " + std::to_string(limits::kMaxFrames - 1) +
                         " (simcap's largest frame count is " + std::to_string(limits::kMaxFrames) +
                         "), got " + std::to_string(frame));
  }
  return static_cast<int>(frame);
}

// A table may leave out rows (their cells read as missing), but a few scattered rows must not
// make the reader allocate a huge grid: beyond a million cells, at least a quarter of the
// `cells` (frames x joints [x cameras]) must have a row.
inline void check_table_density(const CsvReader& csv, std::size_t rows, std::size_t frames,
                                std::size_t cells) {
  constexpr std::size_t kFreeCells = 1'000'000;
  if (cells > kFreeCells && cells / 4 > rows) {
    throw_input_error(csv.path(), 0, "",
                      std::to_string(rows) + " rows for " + std::to_string(frames) +
                          " frames make a grid of " + std::to_string(cells) +
                          " cells; expected rows for at least a quarter of them");
  }
}

// Reads the table at `path`, whose header must be `columns` (frame and joint first).
// `read_value(csv)` parses the current row's value columns and reports bad ones through
// csv.fail. Frames out of range, empty joint names and a joint repeated within a frame are
// Errors naming file:line and column; so is a table too sparse for its grid (see above).
template <typename Value, typename ReadValue>
JointTable<Value> read_joint_table(const std::filesystem::path& path,
                                   const std::vector<std::string>& columns, const Value& missing,
                                   ReadValue read_value) {
  CsvReader csv(path, columns);
  JointTable<Value> table;
  std::map<int, std::map<int, Value>> rows;
  std::unordered_map<std::string, int> joint_index;
  std::size_t row_count = 0;
  while (csv.next()) {
    const int frame = read_frame_number(csv, 0);
    const std::string& name = csv.text(1);
    if (name.empty()) csv.fail(1, "empty joint name");
    const auto [it, added] = joint_index.emplace(name, static_cast<int>(table.joints.size()));
    if (added) table.joints.push_back(name);
    if (!rows[frame].emplace(it->second, read_value(csv)).second) {
      csv.fail(1, "joint '" + name + "' repeated in frame " + std::to_string(frame));
    }
    ++row_count;
  }
  check_table_density(csv, row_count, rows.size(), rows.size() * table.joints.size());
  for (const auto& [frame, joints] : rows) {
    table.frames.push_back(frame);
    auto& row = table.values.emplace_back(table.joints.size(), missing);
    for (const auto& [j, value] : joints) row[j] = value;
  }
  return table;
}

}  // namespace simcap
