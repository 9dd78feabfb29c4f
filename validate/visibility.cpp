#include "validate/visibility.h"

#include <algorithm>
#include <map>
#include <unordered_map>

#include "core/csv.h"
#include "core/error.h"
#include "core/joint_table.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

constexpr VisibilityLabel kLabelled[] = {VisibilityLabel::visible, VisibilityLabel::self_occluded,
                                         VisibilityLabel::scene_occluded,
                                         VisibilityLabel::out_of_frame};

int index_of(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

std::string_view visibility_label_name(VisibilityLabel v) {
  switch (v) {
    case VisibilityLabel::visible:
      return "visible";
    case VisibilityLabel::self_occluded:
      return "self_occluded";
    case VisibilityLabel::scene_occluded:
      return "scene_occluded";
    case VisibilityLabel::out_of_frame:
      return "out_of_frame";
    case VisibilityLabel::missing:
      break;
  }
  return "missing";
}

std::optional<VisibilityLabel> visibility_label_of(std::string_view name) {
  for (const VisibilityLabel v : kLabelled) {
    if (visibility_label_name(v) == name) return v;
  }
  return std::nullopt;
}

int VisibilityTable::frame_index(int frame) const {
  const auto it = std::lower_bound(frames.begin(), frames.end(), frame);
  return it != frames.end() && *it == frame ? static_cast<int>(it - frames.begin()) : -1;
}

int VisibilityTable::joint_index(const std::string& name) const {
  return index_of(joints, name);
}

VisibilityTable read_visibility_table(const fs::path& path,
                                      const std::vector<std::string>& cameras) {
  CsvReader csv(path, kJoints2dColumns);
  VisibilityTable table;
  table.cameras = cameras;
  // frame -> (joint, camera) -> label; ordered so that the table comes out with ascending frames.
  std::map<int, std::map<std::pair<int, int>, VisibilityLabel>> rows;
  std::unordered_map<std::string, int> joint_index;
  std::size_t row_count = 0;
  while (csv.next()) {
    const int frame = read_frame_number(csv, 0);
    const int cam = index_of(cameras, csv.text(1));
    if (cam < 0) {
      csv.fail(1, "unknown camera '" + csv.text(1) + "'; the calibration has " + joined(cameras));
    }
    const std::string& joint = csv.text(2);
    if (joint.empty()) csv.fail(2, "empty joint name");
    const auto [it, added] = joint_index.emplace(joint, static_cast<int>(table.joints.size()));
    if (added) table.joints.push_back(joint);
    const int j = it->second;
    const std::string& label = csv.text(6);
    const std::optional<VisibilityLabel> v = visibility_label_of(label);
    if (!v) {
      csv.fail(6, "expected visible, self_occluded, scene_occluded or out_of_frame, got '" + label +
                      "'");
    }
    if (!rows[frame].emplace(std::pair{j, cam}, *v).second) {
      csv.fail(2, "joint '" + joint + "' repeated for camera " + cameras[cam] + " in frame " +
                      std::to_string(frame));
    }
    ++row_count;
  }
  check_table_density(csv, row_count, rows.size(),
                      rows.size() * table.joints.size() * cameras.size());
  for (const auto& [frame, labels] : rows) {
    table.frames.push_back(frame);
    auto& s = table.status.emplace_back(
        table.joints.size(),
        std::vector<VisibilityLabel>(cameras.size(), VisibilityLabel::missing));
    for (const auto& [key, v] : labels) s[key.first][key.second] = v;
  }
  return table;
}

}  // namespace simcap
