// The colour classes of the region cost (the thesis's skin, head and clothes), learned on the
// first frame under its known pose: every colour cell of the body model is sampled where it shows
// inside the silhouette, cells of alike colour are merged into one class, and each class keeps a
// Gaussian of the pixel colour by which later images are segmented.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "tracker/gomez/label_renderer.h"

namespace simcap::tracker::gomez {

inline constexpr int kMaxColourClasses = 8;

struct ColourOptions {
  int min_samples = 12;  // pixels a cell needs to teach its colour
  // Cells join a class when the squared Mahalanobis distance of their mean colour to the
  // class's Gaussian is below this (9: three standard deviations).
  double merge_distance2 = 9.0;
  // A cell founds a new class only when its chromaticity's standard deviation is below this: a
  // cell across a sleeve's edge or the belt mixes two colours, and its mean is neither.
  double pure_chroma = 0.03;
  // A pixel belongs to the nearest class when its squared Mahalanobis distance is below this
  // (chi-square, 3 degrees of freedom, 99.9%); otherwise to none.
  double accept_distance2 = 16.3;
  // Standard deviations added to every class's colour feature (chromaticity r, g and log
  // brightness), so that a flat-shaded cell does not give a degenerate Gaussian.
  double chroma_floor = 0.015;
  double brightness_floor = 0.08;
};

class ColourClasses {
 public:
  ColourClasses() = default;
  // From a colour image (CV_8UC3, any fixed channel order), its silhouette (CV_8UC1) and the
  // cells of `shape` rendered at full resolution in the same pose (`cells`, for `view` with
  // factor 1). Throws Error when no cell shows enough pixels.
  ColourClasses(const cv::Mat& image, const cv::Mat& silhouette, const LabelImage& cells,
                const View& view, const BodyShape& shape, const ColourOptions& options = {});

  // One class for every colour and every cell: the region cost becomes the silhouette's
  // non-overlap (the upright start, before any colour is known).
  static ColourClasses uniform(int cell_count);

  int count() const { return count_; }  // classes are 1..count()
  // Class of each colour cell of the body (1..count()).
  const std::vector<std::uint8_t>& cell_class() const { return cell_class_; }
  // Class of a pixel's colour, 0 when it fits none.
  std::uint8_t classify(const std::uint8_t* pixel) const {
    return lut_[(pixel[0] >> 3) << 10 | (pixel[1] >> 3) << 5 | (pixel[2] >> 3)];
  }
  // Mean colour of each class (channel order of the learning image), for drawings.
  const std::vector<Eigen::Vector3d>& class_colour() const { return colour_; }

 private:
  int count_ = 0;
  std::vector<std::uint8_t> cell_class_;
  std::vector<std::uint8_t> lut_;  // 32 x 32 x 32 quantized colours
  std::vector<Eigen::Vector3d> colour_;
};

}  // namespace simcap::tracker::gomez
