#include "tracker/unzueta/gesture_signals.h"

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/error.h"

namespace simcap::tracker {

BodySignals body_signals(const JointTrack& track, const std::string& source) {
  const std::array<std::string, 8> names = {"humanoid_root", "l_hip",         "r_hip",
                                            "skullbase",     "l_radiocarpal", "r_radiocarpal",
                                            "l_talocrural",  "r_talocrural"};
  std::array<int, 8> j{};
  for (size_t k = 0; k < names.size(); ++k) {
    j[k] = track.joint_index(names[k]);
    if (j[k] < 0) throw Error(source + ": no joint '" + names[k] + "'; expected the HE15 joints");
  }
  BodySignals s;
  s.frames = track.frames;
  for (size_t f = 0; f < track.frames.size(); ++f) {
    const auto& p = track.positions[f];
    for (size_t k = 0; k < names.size(); ++k) {
      if (!p[j[k]].allFinite()) {
        throw Error(source + ": frame " + std::to_string(track.frames[f]) + " has no '" + names[k] +
                    "'");
      }
    }
    Eigen::Vector3d x = p[j[1]] - p[j[2]];
    x.y() = 0;
    // A degenerate hip line (never on a body) keeps the world's X.
    x = x.norm() > 1e-9 ? Eigen::Vector3d(x.normalized()) : Eigen::Vector3d::UnitX();
    Eigen::Matrix3d r;
    r.col(0) = x;
    r.col(1) = Eigen::Vector3d::UnitY();
    r.col(2) = x.cross(Eigen::Vector3d::UnitY());
    auto local = [&](int k) -> Eigen::Vector3d { return r.transpose() * (p[j[k]] - p[j[0]]); };
    s.hand[0].push_back(local(4));
    s.hand[1].push_back(local(5));
    Eigen::Matrix<double, 15, 1> pose;
    pose << local(3), local(4), local(5), local(6), local(7);
    s.pose.push_back(pose);
  }
  return s;
}

namespace {

template <typename Series>
void smooth_series(Series& series, double sigma) {
  if (sigma <= 0 || series.size() < 2) return;
  using V = typename Series::value_type;
  const int n = static_cast<int>(series.size());
  const int dims = static_cast<int>(V::RowsAtCompileTime);
  cv::Mat m(n, dims, CV_64F);
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < dims; ++d) m.at<double>(i, d) = series[static_cast<size_t>(i)][d];
  }
  cv::Mat out;
  // Down the columns only: a (1 x ksize) kernel across features would mix them.
  cv::GaussianBlur(m, out, cv::Size(1, 2 * static_cast<int>(std::ceil(3 * sigma)) + 1), 0, sigma,
                   cv::BORDER_REPLICATE);
  for (int i = 0; i < n; ++i) {
    for (int d = 0; d < dims; ++d) series[static_cast<size_t>(i)][d] = out.at<double>(i, d);
  }
}

}  // namespace

void smooth_path(std::vector<Eigen::Vector3d>& path, double sigma) {
  smooth_series(path, sigma);
}

void smooth_signals(BodySignals& s, double sigma) {
  smooth_series(s.hand[0], sigma);
  smooth_series(s.hand[1], sigma);
  smooth_series(s.pose, sigma);
}

}  // namespace simcap::tracker
