#include "sim/mask_boxes.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.h"

namespace simcap {

std::vector<MaskBox> mask_boxes(const cv::Mat& mask, int actors) {
  if (mask.type() != CV_8UC1) throw Error("mask_boxes: expected an 8-bit one-channel mask");
  std::vector<MaskBox> boxes(actors);
  for (int y = 0; y < mask.rows; ++y) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < mask.cols; ++x) {
      // Most of a mask is background: skip it eight pixels at a time.
      if (x % 8 == 0 && x + 8 <= mask.cols) {
        std::uint64_t eight;
        std::memcpy(&eight, row + x, 8);
        if (eight == 0) {
          x += 7;
          continue;
        }
      }
      if (!row[x]) continue;
      const int a = actors == 1 ? 0 : row[x] - 1;
      if (a < 0 || a >= actors) {
        throw Error("mask_boxes: mask value " + std::to_string(row[x]) + " names no actor of " +
                    std::to_string(actors));
      }
      MaskBox& b = boxes[a];
      if (b.pixels == 0) {
        b.x0 = b.x1 = x;
        b.y0 = b.y1 = y;
      }
      b.x0 = std::min(b.x0, x);
      b.x1 = std::max(b.x1, x);
      b.y0 = std::min(b.y0, y);
      b.y1 = std::max(b.y1, y);
      ++b.pixels;
    }
  }
  return boxes;
}

}  // namespace simcap
