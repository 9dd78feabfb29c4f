// The --inspect picture of the monocular tracker (inspection.h).
#include "tracker/gomez/inspection.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker::gomez {

cv::Mat inspection_image(const PoseScorer& scorer, const ColourClasses& classes,
                         const FrameCues& cues, const State& x, int zoom) {
  const int W = cues.view.width, H = cues.view.height;
  LabelImage labels;
  scorer.render(x, cues.view, labels);
  const auto colour_of = [&](int cls) {
    if (cls <= 0) return cv::Vec3b(0, 0, 0);
    const Eigen::Vector3d& c = classes.class_colour()[cls - 1];
    return cv::Vec3b(static_cast<std::uint8_t>(c[0]), static_cast<std::uint8_t>(c[1]),
                     static_cast<std::uint8_t>(c[2]));
  };
  cv::Mat seen(H, W, CV_8UC3), model(H, W, CV_8UC3), distance(H, W, CV_8UC3);
  const float far = std::max(1.0f, std::min(cues.far, 20.0f));
  for (int v = 0; v < H; ++v) {
    for (int u = 0; u < W; ++u) {
      seen.at<cv::Vec3b>(v, u) = colour_of(cues.cls_at(u, v));
      const std::uint8_t cell = labels.at(u, v);
      const bool contour =
          cell != kNoCell && on_contour(labels, u, v, scorer.options().occlusion_gap_m);
      model.at<cv::Vec3b>(v, u) = cell == kNoCell ? cv::Vec3b(0, 0, 0)
                                  : contour       ? cv::Vec3b(255, 255, 255)
                                                  : colour_of(scorer.cell_class()[cell]);
      const float d = cues.distance[static_cast<size_t>(v) * W + u];
      const auto g = static_cast<std::uint8_t>(255 * (1 - std::min(d, far) / far));
      distance.at<cv::Vec3b>(v, u) = contour ? cv::Vec3b(0, 0, 255) : cv::Vec3b(g, g, g);
    }
  }
  cv::Mat row;
  cv::hconcat(std::vector<cv::Mat>{cues.small, seen, model, distance}, row);
  cv::Mat big;
  cv::resize(row, big, {}, zoom, zoom, cv::INTER_NEAREST);
  return big;
}

}  // namespace simcap::tracker::gomez
