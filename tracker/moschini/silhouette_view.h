// One camera's silhouette as the joint refinement reads it: whether a pixel is on it, and for
// one that is not, the nearest that is, so that a model point projecting outside can be pulled
// back inside.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <unordered_map>

#include "core/camera.h"

namespace simcap::tracker {

class SilhouetteView {
 public:
  // `silhouette`: 8-bit, non-zero on the person (shared, not copied). `camera` must outlive the
  // view. Queries beyond the silhouette's bounding box grown by `margin_px` are moved onto the
  // box's edge first (the pull still points at the silhouette, and no search goes farther).
  SilhouetteView(const Camera& camera, const cv::Mat& silhouette, int margin_px = 24);
  const Camera& camera() const { return *camera_; }
  bool empty() const { return box_.empty(); }
  // Image pixel (column, row) of the silhouette pixel nearest to (u, v), which must lie in the
  // image; (u, v) itself when it is on the silhouette. Not for an empty view. Answers are
  // remembered, so this is not thread-safe.
  Eigen::Vector2i nearest(int u, int v) const;
  bool inside(int u, int v) const;
  const cv::Mat& silhouette() const { return silhouette_; }

 private:
  const Camera* camera_;
  cv::Mat silhouette_;
  cv::Rect box_;  // the silhouette's bounding box grown by the margin, within the image
  mutable std::unordered_map<int, int> found_;  // query pixel -> nearest (row * width + column)
};

}  // namespace simcap::tracker
