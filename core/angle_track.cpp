#include "core/angle_track.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "core/csv.h"
#include "core/joint_table.h"

namespace simcap {
namespace fs = std::filesystem;

int AngleTrack::joint_index(const std::string& name) const {
  return find_joint(joints, name);
}

void AngleTrack::add_frame(int frame, std::vector<Eigen::Quaterniond> q) {
  frames.push_back(frame);
  rotations.push_back(std::move(q));
}

void write_angle_track(const fs::path& path, const AngleTrack& track) {
  CsvWriter csv(path, kAnglesColumns);
  char buf[192];
  for (size_t f = 0; f < track.frames.size(); ++f) {
    for (size_t j = 0; j < track.joints.size(); ++j) {
      const Eigen::Quaterniond& q = track.rotations[f][j];
      std::snprintf(buf, sizeof buf, "%d,%s,%.9f,%.9f,%.9f,%.9f\n", track.frames[f],
                    track.joints[j].c_str(), q.w(), q.x(), q.y(), q.z());
      csv.out() << buf;
    }
  }
  csv.commit();
}

AngleTrack read_angle_track(const fs::path& path) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  JointTable<Eigen::Quaterniond> table = read_joint_table(
      path, kAnglesColumns, Eigen::Quaterniond(nan, nan, nan, nan), [](const CsvReader& csv) {
        const Eigen::Quaterniond q(csv.number(2), csv.number(3), csv.number(4), csv.number(5));
        if (!(std::abs(q.norm() - 1.0) <= 1e-3)) csv.fail(2, "expected a unit quaternion");
        return q.normalized();
      });
  return {std::move(table.joints), std::move(table.frames), std::move(table.values)};
}

}  // namespace simcap
