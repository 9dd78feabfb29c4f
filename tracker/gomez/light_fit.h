// The light of the arm bones' shading (bone_shading.h) fitted on the first frame with the start
// pose: every body pixel's grey against the Lambert term of its capsule's surface normal there,
// the light's direction searched over the sky with each colour class's grey line fitted by least
// squares at every direction.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "tracker/gomez/bone_shading.h"

namespace simcap::tracker::gomez {

// One body pixel: its capsule's outward normal there (camera coordinates), colour class and grey.
struct ShadedPixel {
  Eigen::Vector3d normal;
  std::uint8_t cls = 0;
  double grey = 0;
};

// The pixels of `cells` (`shape` posed by `world`, rendered in `view` at full resolution) inside
// `silhouette`, with the normal of the capsule that drew them, where the sight line meets the
// capsule within `rim` of its radius from its axis (out there the capsule's outline is not the
// body's, and the pixels mix in the background). `image` CV_8UC3 (BGR), `silhouette` CV_8UC1.
std::vector<ShadedPixel> shaded_pixels(const BodyShape& shape,
                                       const std::vector<Eigen::Isometry3d>& world,
                                       const View& view, const LabelImage& cells,
                                       const cv::Mat& image, const cv::Mat& silhouette,
                                       const std::vector<std::uint8_t>& cell_class,
                                       double rim = 0.6);

struct LightFit {
  Lighting lighting;
  double rms_grey = 0;  // the fit's residual per pixel
  int pixels = 0;       // that it kept
};

// The direction (of `directions` spread evenly over the hemisphere about `up`, camera
// coordinates) and each class's grey = albedo max(0, n . l) + offset that minimise the squared
// grey residual over `pixels`. The light is taken from above: shading alone cannot tell a light
// from the one turned half a turn about the camera's axis once the bones may be flipped (turned
// so, a bone is its own depth flip). A class whose slope comes out negative is held flat; a
// direction that needs a negative offset or a class brighter than 255 is not taken. The fit is
// made twice, the second time without the pixels the first misses by more than twice its rms.
// No pixels (or no admissible direction): an unknown lighting.
LightFit fit_light(const std::vector<ShadedPixel>& pixels, const Eigen::Vector3d& up,
                   int directions = 3000);

}  // namespace simcap::tracker::gomez
