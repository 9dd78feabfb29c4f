#include "tracker/moschini/silhouette_view.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tracker/common/mask_box.h"

namespace simcap::tracker {

SilhouetteView::SilhouetteView(const Camera& camera, const cv::Mat& silhouette, int margin_px)
    : camera_(&camera), silhouette_(silhouette) {
  const cv::Rect person = mask_box(silhouette);
  if (person.empty()) return;
  box_ = cv::Rect(person.x - margin_px, person.y - margin_px, person.width + 2 * margin_px,
                  person.height + 2 * margin_px) &
         cv::Rect(0, 0, silhouette.cols, silhouette.rows);
}

bool SilhouetteView::inside(int u, int v) const {
  return u >= 0 && v >= 0 && u < silhouette_.cols && v < silhouette_.rows &&
         silhouette_.at<std::uint8_t>(v, u) != 0;
}

Eigen::Vector2i SilhouetteView::nearest(int u, int v) const {
  u = std::clamp(u, box_.x, box_.x + box_.width - 1);
  v = std::clamp(v, box_.y, box_.y + box_.height - 1);
  const int width = silhouette_.cols;
  const auto [it, fresh] = found_.try_emplace(v * width + u, -1);
  if (fresh) {
    // Rings of growing Chebyshev radius r around (u, v): a pixel on ring r lies at least r away,
    // so once r passes the nearest distance found, no nearer pixel is left.
    double best = std::numeric_limits<double>::infinity();
    const int last = std::max(box_.width, box_.height);  // the box holds every silhouette pixel
    for (int r = 0; r <= best && r <= last; ++r) {
      const int top = v - r, bottom = v + r, left = u - r, right = u + r;
      auto visit = [&](int x, int y) {
        if (!inside(x, y)) return;
        const double d = std::hypot(x - u, y - v);
        if (d < best) best = d, it->second = y * width + x;
      };
      for (int x = left; x <= right; ++x) {
        visit(x, top);
        if (r > 0) visit(x, bottom);
      }
      for (int y = top + 1; y < bottom; ++y) visit(left, y), visit(right, y);
    }
  }
  return {it->second % width, it->second / width};
}

}  // namespace simcap::tracker
