// Each actor's pixels in an actor mask (the renderer's mask: 255 for a lone actor, 1 + actor
// index with several): bounding box and pixel count, the bbox and area of COCO annotations.
#pragma once

#include <opencv2/core/mat.hpp>
#include <vector>

namespace simcap {

struct MaskBox {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive pixel bounds; empty when x1 < x0
  long pixels = 0;
  bool empty() const { return pixels == 0; }
};

// One box per actor, in actor order, of a CV_8UC1 mask rendered with `actors` actors.
std::vector<MaskBox> mask_boxes(const cv::Mat& mask, int actors);

}  // namespace simcap
