#include "tracker/unzueta/depth_lookup.h"

#include <algorithm>
#include <cmath>

namespace simcap::tracker {

std::optional<double> depth_quantile(const cv::Mat& depth, const std::vector<cv::Point>& points,
                                     double quantile) {
  std::vector<float> z;
  for (const cv::Point& p : points) {
    const int x = p.x, y = p.y;
    if (x < 0 || y < 0 || x >= depth.cols || y >= depth.rows) continue;
    const float d = depth.at<float>(y, x);
    if (std::isfinite(d) && d > 0) z.push_back(d);
  }
  if (z.empty()) return std::nullopt;
  const auto k =
      std::min(z.size() - 1, static_cast<size_t>(quantile * static_cast<double>(z.size())));
  std::nth_element(z.begin(), z.begin() + static_cast<std::ptrdiff_t>(k), z.end());
  return z[k];
}

std::optional<PartDepth> part_depth(const cv::Mat& depth, const std::vector<cv::Point>& points,
                                    double surface_quantile, double order_quantile,
                                    double thickness) {
  auto surface = depth_quantile(depth, points, surface_quantile);
  if (!surface) return std::nullopt;
  if (thickness > 0) {
    surface = std::min(*surface, *depth_quantile(depth, points, kNearQuantile) + thickness);
  }
  return PartDepth{*surface, *depth_quantile(depth, points, order_quantile)};
}

std::vector<cv::Point> mask_samples(const cv::Mat& mask, cv::Point2d centre, int half, int step) {
  std::vector<cv::Point> out;
  const int cx = static_cast<int>(std::lround(centre.x)),
            cy = static_cast<int>(std::lround(centre.y));
  for (int y = std::max(0, cy - half); y <= std::min(mask.rows - 1, cy + half); y += step) {
    for (int x = std::max(0, cx - half); x <= std::min(mask.cols - 1, cx + half); x += step) {
      if (mask.at<unsigned char>(y, x)) out.emplace_back(x, y);
    }
  }
  return out;
}

Eigen::Vector3d point_at_depth(const Camera& camera, cv::Point2d pixel, double z) {
  const Eigen::Vector3d ray = camera.unproject_camera({pixel.x, pixel.y});
  return camera.to_world(ray * (z / ray.z()));
}

Eigen::Vector3d centre_behind_surface(const Camera& camera, cv::Point2d pixel, double surface_z,
                                      double behind) {
  const Eigen::Vector3d ray = camera.unproject_camera({pixel.x, pixel.y});
  return camera.to_world(ray * (surface_z / ray.z()) + behind * ray);
}

}  // namespace simcap::tracker
