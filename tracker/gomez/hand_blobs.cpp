// Hand regions of the segmented image (hand_blobs.h).
#include "tracker/gomez/hand_blobs.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker::gomez {

Eigen::Vector2d HandBlob::farthest_from(const Eigen::Vector2d& from) const {
  Eigen::Vector2d best = from;
  double d2 = -1;
  for (const Eigen::Vector2d& p : pixels) {
    const double e2 = (p - from).squaredNorm();
    if (e2 > d2) {
      d2 = e2;
      best = p;
    }
  }
  return best;
}

std::vector<HandBlob> hand_blobs(const FrameCues& cues, std::uint8_t cls, int min_area,
                                 int max_blobs) {
  const View& view = cues.view;
  std::vector<HandBlob> out;
  if (view.width <= 0 || view.height <= 0 || cls == 0) return out;
  cv::Mat mask(view.height, view.width, CV_8UC1);
  for (int v = 0; v < view.height; ++v) {
    std::uint8_t* m = mask.ptr<std::uint8_t>(v);
    for (int u = 0; u < view.width; ++u) m[u] = cues.cls_at(u, v) == cls ? 255 : 0;
  }
  cv::Mat labels;
  const int n = cv::connectedComponents(mask, labels, 4, CV_32S);
  std::vector<HandBlob> blobs(std::max(0, n - 1));
  for (int v = 0; v < view.height; ++v) {
    const int* l = labels.ptr<int>(v);
    for (int u = 0; u < view.width; ++u) {
      if (l[u] == 0) continue;
      // Working pixel centres sit at integers: back to the full-resolution pixel they cover.
      blobs[l[u] - 1].pixels.emplace_back(view.x0 + (u + 0.5) * view.factor - 0.5,
                                          view.y0 + (v + 0.5) * view.factor - 0.5);
    }
  }
  for (HandBlob& b : blobs) {
    if (static_cast<int>(b.pixels.size()) >= min_area) out.push_back(std::move(b));
  }
  std::stable_sort(out.begin(), out.end(), [](const HandBlob& a, const HandBlob& b) {
    return a.pixels.size() > b.pixels.size();
  });
  if (static_cast<int>(out.size()) > max_blobs) out.resize(std::max(0, max_blobs));
  return out;
}

}  // namespace simcap::tracker::gomez
