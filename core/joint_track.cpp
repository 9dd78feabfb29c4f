#include "core/joint_track.h"

#include <cstdio>
#include <limits>

#include "core/csv.h"
#include "core/joint_table.h"

namespace simcap {
namespace fs = std::filesystem;

int JointTrack::joint_index(const std::string& name) const {
  return find_joint(joints, name);
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
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  JointTable<Eigen::Vector3d> table =
      read_joint_table(path, kJoints3dColumns, nan, [](const CsvReader& csv) {
        const Eigen::Vector3d p(csv.number(2), csv.number(3), csv.number(4));
        if (!p.allFinite()) csv.fail(2, "position must be finite");
        return p;
      });
  return {std::move(table.joints), std::move(table.frames), std::move(table.values)};
}

}  // namespace simcap
