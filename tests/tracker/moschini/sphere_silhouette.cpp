#include "tests/tracker/moschini/sphere_silhouette.h"

namespace simcap::testing {

cv::Mat sphere_silhouette(const Camera& cam, const Eigen::Vector3d& c, double radius) {
  cv::Mat mask(cam.height, cam.width, CV_8UC1, cv::Scalar(0));
  const Eigen::Vector3d o = cam.centre();
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      const Eigen::Vector3d d = cam.unproject({u, v});
      const double along = (c - o).dot(d);
      if (along > 0 && ((c - o) - along * d).norm() <= radius) mask.at<std::uint8_t>(v, u) = 255;
    }
  }
  return mask;
}

}  // namespace simcap::testing
