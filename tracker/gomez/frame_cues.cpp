// One frame's region and edge cues (frame_cues.h).
#include "tracker/gomez/frame_cues.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tracker/common/mask_box.h"

namespace simcap::tracker::gomez {

FrameCues make_cues(const Camera& camera, const cv::Mat& image, const cv::Mat& silhouette,
                    const ColourClasses& classes, const cv::Rect& hint, const CueOptions& options) {
  const cv::Rect person = mask_box(silhouette);
  const cv::Rect image_rect(0, 0, image.cols, image.rows);
  cv::Rect box = person | hint;
  if (box.empty()) box = image_rect;
  const int tall = std::max(person.height, hint.height);
  const int factor =
      std::max(1, static_cast<int>(std::lround(static_cast<double>(std::max(tall, 1)) /
                                               std::max(1, options.work_height))));
  const int grow = static_cast<int>(std::ceil(options.margin * std::max(tall, 1)));
  box = cv::Rect(box.x - grow, box.y - grow, box.width + 2 * grow, box.height + 2 * grow) &
        image_rect;
  // Whole working pixels only.
  box.width -= box.width % factor;
  box.height -= box.height % factor;

  FrameCues cues;
  if (!person.empty() && person.y + person.height < image.rows) {
    cues.feet_row = person.y + person.height - 0.5;
  }
  if (!person.empty() && person.y > 0) cues.top_row = person.y - 0.5;
  cues.view = {&camera, box.x, box.y, factor, box.width / factor, box.height / factor};
  const int W = cues.view.width, H = cues.view.height;
  cues.cls.assign(static_cast<size_t>(W) * H, 0);
  cues.distance.assign(static_cast<size_t>(W) * H, static_cast<float>(W + H));
  cues.far = static_cast<float>(W + H);
  if (W <= 0 || H <= 0) return cues;

  cv::Mat mask_small;
  cv::resize(image(box), cues.small, cv::Size(W, H), 0, 0, cv::INTER_AREA);
  cv::resize(silhouette(box), mask_small, cv::Size(W, H), 0, 0, cv::INTER_AREA);
  cv::Mat inside = mask_small >= 128;
  for (int v = 0; v < H; ++v) {
    const std::uint8_t* m = inside.ptr<std::uint8_t>(v);
    const std::uint8_t* p = cues.small.ptr<std::uint8_t>(v);
    for (int u = 0; u < W; ++u) {
      if (!m[u]) continue;
      const std::uint8_t c = classes.classify(p + 3 * u);
      cues.cls[static_cast<size_t>(v) * W + u] = c;
      ++cues.class_area[c];
    }
  }
  cues.class_area[0] = 0;

  cv::Mat grey, edges, band;
  cv::cvtColor(cues.small, grey, cv::COLOR_BGR2GRAY);
  cues.grey.resize(static_cast<size_t>(W) * H);
  for (int v = 0; v < H; ++v) {
    std::copy_n(grey.ptr<std::uint8_t>(v), W, cues.grey.begin() + static_cast<size_t>(v) * W);
  }
  cv::Canny(grey, edges, options.canny_low, options.canny_high, 3, true);
  const int b = std::max(0, options.edge_band_px);
  cv::dilate(inside, band, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * b + 1, 2 * b + 1}));
  edges &= band;
  if (cv::countNonZero(edges) > 0) {
    cv::Mat not_edge = edges == 0, distance;
    cv::distanceTransform(not_edge, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
    double high = 0;
    cv::minMaxLoc(distance, nullptr, &high);
    cues.far = static_cast<float>(high);
    for (int v = 0; v < H; ++v) {
      std::copy_n(distance.ptr<float>(v), W, cues.distance.begin() + static_cast<size_t>(v) * W);
    }
  }
  return cues;
}

}  // namespace simcap::tracker::gomez
