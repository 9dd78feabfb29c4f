#include "tracker/common/mask_box.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace simcap::tracker {

cv::Rect mask_box(const cv::Mat& mask) {
  // The rows with any byte set, and the columns set in the OR of all rows.
  const int words = mask.cols / 8;
  std::vector<std::uint64_t> any(static_cast<size_t>(words), 0);
  std::vector<std::uint8_t> tail(static_cast<size_t>(mask.cols - 8 * words), 0);
  int top = -1, bottom = -1;
  for (int v = 0; v < mask.rows; ++v) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(v);
    std::uint64_t hit = 0;
    for (int w = 0; w < words; ++w) {
      std::uint64_t word;
      std::memcpy(&word, row + 8 * w, 8);
      any[w] |= word;
      hit |= word;
    }
    for (size_t u = 0; u < tail.size(); ++u) {
      tail[u] |= row[8 * words + u];
      hit |= row[8 * words + u];
    }
    if (hit) bottom = v, top = top < 0 ? v : top;
  }
  if (top < 0) return {};
  auto set = [&](int u) {
    if (u >= 8 * words) return tail[u - 8 * words] != 0;
    std::uint8_t bytes[8];
    std::memcpy(bytes, &any[u / 8], 8);
    return bytes[u % 8] != 0;
  };
  int left = 0, right = mask.cols - 1;
  while (!set(left)) ++left;
  while (!set(right)) --right;
  return {left, top, right - left + 1, bottom - top + 1};
}

}  // namespace simcap::tracker
