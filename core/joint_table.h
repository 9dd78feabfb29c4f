// Reads the `frame,joint,<value columns>` tables of a dataset (joints3d.csv, angles.csv): one
// row per frame and joint, any order, gathered into frames x joints with a filler for missing rows.
#pragma once

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/csv.h"

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

// Reads the table at `path`, whose header must be `columns` (frame and joint first).
// `read_value(csv)` parses the current row's value columns and reports bad ones through
// csv.fail. Negative frames, empty joint names and a joint repeated within a frame are Errors
// naming file:line and column.
template <typename Value, typename ReadValue>
JointTable<Value> read_joint_table(const std::filesystem::path& path,
                                   const std::vector<std::string>& columns, const Value& missing,
                                   ReadValue read_value) {
  CsvReader csv(path, columns);
  JointTable<Value> table;
  std::map<int, std::map<int, Value>> rows;
  while (csv.next()) {
    const long frame = csv.integer(0);
    if (frame < 0) csv.fail(0, "frame numbers start at 0");
    const std::string& name = csv.text(1);
    if (name.empty()) csv.fail(1, "empty joint name");
    int j = find_joint(table.joints, name);
    if (j < 0) {
      j = static_cast<int>(table.joints.size());
      table.joints.push_back(name);
    }
    if (!rows[static_cast<int>(frame)].emplace(j, read_value(csv)).second) {
      csv.fail(1, "joint '" + name + "' repeated in frame " + std::to_string(frame));
    }
  }
  for (const auto& [frame, joints] : rows) {
    table.frames.push_back(frame);
    auto& row = table.values.emplace_back(table.joints.size(), missing);
    for (const auto& [j, value] : joints) row[j] = value;
  }
  return table;
}

}  // namespace simcap
