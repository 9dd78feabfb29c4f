#include "validate/angle_track.h"

#include <cmath>
#include <limits>

#include "core/joint_table.h"

namespace simcap {
namespace fs = std::filesystem;

int AngleTrack::joint_index(const std::string& name) const {
  return find_joint(joints, name);
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
