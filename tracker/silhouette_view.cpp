#include "tracker/silhouette_view.h"

#include <opencv2/imgproc.hpp>
#include <vector>

namespace simcap::tracker {

SilhouetteView::SilhouetteView(const Camera& camera, const cv::Mat& silhouette, int margin_px)
    : camera_(&camera) {
  const cv::Rect person = cv::boundingRect(silhouette);
  if (person.empty()) return;
  box_ = cv::Rect(person.x - margin_px, person.y - margin_px, person.width + 2 * margin_px,
                  person.height + 2 * margin_px) &
         cv::Rect(0, 0, silhouette.cols, silhouette.rows);
  // distanceTransform labels every pixel with its nearest zero pixel: make the person zero.
  const cv::Mat background = silhouette(box_) == 0;
  cv::Mat distance, labels;
  cv::distanceTransform(background, distance, labels, cv::DIST_L2, cv::DIST_MASK_5,
                        cv::DIST_LABEL_PIXEL);
  std::vector<int> pixel_of_label(static_cast<size_t>(box_.area()) + 1, 0);
  for (int v = 0; v < box_.height; ++v) {
    const std::uint8_t* b = background.ptr<std::uint8_t>(v);
    const int* l = labels.ptr<int>(v);
    for (int u = 0; u < box_.width; ++u) {
      if (!b[u]) pixel_of_label[l[u]] = v * box_.width + u;
    }
  }
  nearest_.create(box_.size(), CV_32S);
  for (int v = 0; v < box_.height; ++v) {
    const int* l = labels.ptr<int>(v);
    int* n = nearest_.ptr<int>(v);
    for (int u = 0; u < box_.width; ++u) n[u] = pixel_of_label[l[u]];
  }
}

Eigen::Vector2i SilhouetteView::nearest(int u, int v) const {
  const int bu = std::clamp(u - box_.x, 0, box_.width - 1);
  const int bv = std::clamp(v - box_.y, 0, box_.height - 1);
  const int i = nearest_.at<int>(bv, bu);
  return {box_.x + i % box_.width, box_.y + i / box_.width};
}

bool SilhouetteView::inside(int u, int v) const {
  const int bu = u - box_.x, bv = v - box_.y;
  if (bu < 0 || bv < 0 || bu >= box_.width || bv >= box_.height) return false;
  return nearest_.at<int>(bv, bu) == bv * box_.width + bu;
}

}  // namespace simcap::tracker
