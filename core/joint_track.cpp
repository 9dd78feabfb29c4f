#include "core/joint_track.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

#include "core/csv.h"

namespace simcap {
namespace fs = std::filesystem;

int JointTrack::joint_index(const std::string& name) const {
  const auto it = std::find(joints.begin(), joints.end(), name);
  return it == joints.end() ? -1 : static_cast<int>(it - joints.begin());
}

void JointTrack::add_frame(int frame, std::vector<Eigen::Vector3d> p) {
  frames.push_back(frame);
  positions.push_back(std::move(p));
}

void write_joint_track(const fs::path& path, const JointTrack& track) {
  CsvWriter csv(path, kJoints3dColumns);
  char buf[160];
  for (size_t f = 0; f < track.frames.size(); ++f) {
    for (size_t j = 0; j < track.joints.size(); ++j) {
      const Eigen::Vector3d& p = track.positions[f][j];
      if (!p.allFinite()) continue;
      std::snprintf(buf, sizeof buf, "%d,%s,%.7f,%.7f,%.7f\n", track.frames[f],
                    track.joints[j].c_str(), p.x(), p.y(), p.z());
      csv.out() << buf;
    }
  }
  csv.commit();
}

JointTrack read_joint_track(const fs::path& path) {
  CsvReader csv(path, kJoints3dColumns);
  JointTrack track;
  std::map<int, std::map<int, Eigen::Vector3d>> rows;
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
    const Eigen::Vector3d p(csv.number(2), csv.number(3), csv.number(4));
    if (!p.allFinite()) csv.fail(2, "position must be finite");
    auto& frame_rows = rows[static_cast<int>(frame)];
    if (!frame_rows.emplace(j, p).second)
      csv.fail(1, "joint '" + name + "' repeated in frame " + std::to_string(frame));
  }
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  for (const auto& [frame, joints] : rows) {
    std::vector<Eigen::Vector3d> p(track.joints.size(), nan);
    for (const auto& [j, pos] : joints) p[j] = pos;
    track.add_frame(frame, std::move(p));
  }
  return track;
}

}  // namespace simcap
