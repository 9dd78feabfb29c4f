// Reading a part's distance off a depth image (the thesis' "single depth camera"): a quantile of
// the z-depth under the part's pixels, robust to a few pixels on the background.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker {

// The `quantile` (0: nearest, 0.5: median) of the finite values of `depth` (CV_32FC1, camera z
// in metres, +inf: nothing) at the pixels nearest `points`; nullopt when none is finite.
std::optional<double> depth_quantile(const cv::Mat& depth, const std::vector<cv::Point>& points,
                                     double quantile);

// A part's two readings of the same pixels: `surface` (the `surface_quantile`) places its 3D
// point, `order` (the `order_quantile`) orders it against overlapping parts for the occlusion
// rule (§3.3.1). A hand seen end-on over its forearm: its nearest surface is the hand, but which
// blob covers which is a question about the blob as a whole. nullopt when no depth is finite.
struct PartDepth {
  double surface = 0, order = 0;
};
// With a `thickness` > 0 the surface lies at most that far behind the part's nearest pixels
// (their kNearQuantile): deeper pixels are of something behind the part.
inline constexpr double kNearQuantile = 0.1;
std::optional<PartDepth> part_depth(const cv::Mat& depth, const std::vector<cv::Point>& points,
                                    double surface_quantile, double order_quantile,
                                    double thickness = 0);

// Grid pixels of `mask` (CV_8UC1) within `half` px of `centre` (a square), every `step` px.
std::vector<cv::Point> mask_samples(const cv::Mat& mask, cv::Point2d centre, int half, int step);

// The world point seen at `pixel` whose camera z is `z`.
Eigen::Vector3d point_at_depth(const Camera& camera, cv::Point2d pixel, double z);

// The world point seen at `pixel` at z-depth `surface_z`, pushed `behind` metres further along
// the viewing ray (from a part's surface to its centre).
Eigen::Vector3d centre_behind_surface(const Camera& camera, cv::Point2d pixel, double surface_z,
                                      double behind);

}  // namespace simcap::tracker
