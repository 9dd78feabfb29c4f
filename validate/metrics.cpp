#include "validate/metrics.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace simcap {

Eigen::VectorXd joint_distances(const Eigen::Matrix3Xd& truth, const Eigen::Matrix3Xd& estimate) {
  if (truth.cols() != estimate.cols()) throw Error("joint_distances: joint counts differ");
  return (estimate - truth).colwise().norm().transpose();
}

Eigen::Matrix3Xd procrustes_aligned(const Eigen::Matrix3Xd& truth,
                                    const Eigen::Matrix3Xd& estimate) {
  if (truth.cols() != estimate.cols()) throw Error("procrustes_aligned: joint counts differ");
  // A similarity needs at least three non-collinear points; fewer leave it undetermined.
  if (truth.cols() < 3) throw Error("procrustes_aligned: needs at least 3 joints");
  const Eigen::Matrix4d T = Eigen::umeyama(estimate, truth, true);
  return (T.topLeftCorner<3, 3>() * estimate).colwise() + T.topRightCorner<3, 1>();
}

double pck(const std::vector<double>& errors, double threshold) {
  if (errors.empty()) return 0.0;
  const auto hits =
      std::count_if(errors.begin(), errors.end(), [threshold](double e) { return e <= threshold; });
  return static_cast<double>(hits) / static_cast<double>(errors.size());
}

double root_mean_square(const std::vector<double>& errors) {
  if (errors.empty()) return 0.0;
  double sum = 0.0;
  for (double e : errors) sum += e * e;
  return std::sqrt(sum / static_cast<double>(errors.size()));
}

double mean_value(const std::vector<double>& values) {
  if (values.empty()) return 0.0;
  return std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
}

double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // 2 atan2(|v|, |w|) of the relative quaternion: arccos of the trace formula loses half the
  // digits near zero, and |w| picks the shorter of q and -q.
  const Eigen::Quaterniond d = a.normalized().conjugate() * b.normalized();
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

std::vector<FailureEpisode> failure_episodes(const std::vector<int>& frames,
                                             const std::vector<double>& per_frame_error,
                                             double threshold) {
  if (frames.size() != per_frame_error.size()) throw Error("failure_episodes: sizes differ");
  std::vector<FailureEpisode> episodes;
  for (size_t i = 0; i < frames.size(); ++i) {
    if (!(per_frame_error[i] > threshold)) continue;
    if (i == 0 || !(per_frame_error[i - 1] > threshold)) {
      episodes.push_back({frames[i], 0, false});
    }
    FailureEpisode& e = episodes.back();
    e.frames = frames[i] - e.first_frame + 1;
    e.recovered = i + 1 < frames.size();
  }
  return episodes;
}

}  // namespace simcap
