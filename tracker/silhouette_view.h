// One camera's silhouette as the joint refinement reads it: for every pixel, the nearest
// silhouette pixel, so that a model point projecting outside can be pulled back inside.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera.h"

namespace simcap::tracker {

class SilhouetteView {
 public:
  // `silhouette`: 8-bit, non-zero on the person. `camera` must outlive the view. The map covers
  // the silhouette's bounding box grown by `margin_px`; beyond it, the nearest pixel of the box's
  // edge stands in (the pull still points at the silhouette).
  SilhouetteView(const Camera& camera, const cv::Mat& silhouette, int margin_px = 24);
  const Camera& camera() const { return *camera_; }
  bool empty() const { return nearest_.empty(); }
  // Image pixel (column, row) of the silhouette pixel nearest to (u, v), which must lie in the
  // image; (u, v) itself when it is on the silhouette. Not for an empty view.
  Eigen::Vector2i nearest(int u, int v) const;
  bool inside(int u, int v) const;

 private:
  const Camera* camera_;
  cv::Rect box_;     // where the map is, in image pixels
  cv::Mat nearest_;  // CV_32S over box_: row * box width + column (box coordinates)
};

}  // namespace simcap::tracker
