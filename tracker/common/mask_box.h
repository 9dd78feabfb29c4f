// The bounding box of a silhouette mask's non-zero pixels, read eight bytes at a time (the
// visual hull and the silhouette views need it every frame; cv::boundingRect tests each pixel).
#pragma once

#include <opencv2/core.hpp>

namespace simcap::tracker {

// An empty rectangle when no pixel is set. `mask`: CV_8UC1.
cv::Rect mask_box(const cv::Mat& mask);

}  // namespace simcap::tracker
