#include "validate/angle_track.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "core/csv.h"

namespace simcap {
namespace fs = std::filesystem;

int AngleTrack::joint_index(const std::string& name) const {
  const auto it = std::find(joints.begin(), joints.end(), name);
  return it == joints.end() ? -1 : static_cast<int>(it - joints.begin());
}

AngleTrack read_angle_track(const fs::path& path) {
  CsvReader csv(path, kAnglesColumns);
  AngleTrack track;
  std::map<int, std::map<int, Eigen::Quaterniond>> rows;
  while (csv.next()) {
    const long frame = csv.integer(0);
    if (frame < 0) csv.fail(0, "frame numbers start at 0");
    const std::string& name = csv.text(1);
    if (name.empty()) csv.fail(1, "empty joint name");
    int j = track.joint_index(name);
    if (j < 0) {
      j = static_cast<int>(track.joints.size());
      track.joints.push_back(name);
    }
    const Eigen::Quaterniond q(csv.number(2), csv.number(3), csv.number(4), csv.number(5));
    if (!(std::abs(q.norm() - 1.0) <= 1e-3)) csv.fail(2, "expected a unit quaternion");
    if (!rows[static_cast<int>(frame)].emplace(j, q.normalized()).second) {
      csv.fail(1, "joint '" + name + "' repeated in frame " + std::to_string(frame));
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const auto& [frame, joints] : rows) {
    track.frames.push_back(frame);
    auto& r =
        track.rotations.emplace_back(track.joints.size(), Eigen::Quaterniond(nan, nan, nan, nan));
    for (const auto& [j, q] : joints) r[j] = q;
  }
  return track;
}

}  // namespace simcap
