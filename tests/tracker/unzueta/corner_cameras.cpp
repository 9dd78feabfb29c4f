#include "tests/tracker/unzueta/corner_cameras.h"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <string>

namespace simcap::tracker {

std::vector<Camera> corner_cameras(int n) {
  std::vector<Camera> cams;
  for (int i = 0; i < n; ++i) {
    const double a = 3.14159265358979 * (0.25 + 2.0 * i / n);
    Camera c = Camera::look_at("cam0" + std::to_string(i), 640, 480, 75 * 3.14159265358979 / 180,
                               {3.4 * std::cos(a), 2.5, 3.4 * std::sin(a)}, {0, 1, 0});
    c.dist << -0.1, 0.03, 0.0005, -0.0005, 0.0;
    cams.push_back(c);
  }
  return cams;
}

Eigen::Vector2d opencv_pixel(const Camera& c, const Eigen::Vector3d& x) {
  cv::Mat k, d, r, t;
  cv::eigen2cv(c.K, k);
  cv::eigen2cv(Eigen::VectorXd(c.dist), d);
  cv::Mat rotation;
  cv::eigen2cv(Eigen::Matrix3d(c.R), rotation);
  cv::Rodrigues(rotation, r);
  cv::eigen2cv(Eigen::Vector3d(c.t), t);
  std::vector<cv::Point3d> in{{x.x(), x.y(), x.z()}};
  std::vector<cv::Point2d> out;
  cv::projectPoints(in, r, t, k, d, out);
  return {out[0].x, out[0].y};
}

}  // namespace simcap::tracker
