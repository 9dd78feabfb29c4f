#include "validate/noisy_detections.h"

#include <cmath>
#include <numbers>
#include <random>

namespace simcap {
namespace {

// Box-Muller on 53-bit uniforms: std::normal_distribution's algorithm is the library's choice,
// this is the same on every platform.
double standard_normal(std::mt19937_64& rng) {
  const double u1 = (static_cast<double>(rng() >> 11) + 1.0) * 0x1p-53;  // (0, 1]
  const double u2 = static_cast<double>(rng() >> 11) * 0x1p-53;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace

Detections detections_from_truth(const KeypointTruth& truth, const TruthNoise& noise) {
  Detections out(truth.layout(), truth.cameras(), truth.frames());
  std::mt19937_64 rng(noise.seed);
  const int cameras = static_cast<int>(truth.cameras().size());
  const int actors = static_cast<int>(truth.actors().size());
  for (int f = 0; f < truth.frames(); ++f) {
    for (int c = 0; c < cameras; ++c) {
      for (int a = 0; a < actors; ++a) {
        const ActorView& view = truth.at(f, c, a);
        if (!view.annotated) continue;
        DetectedPerson person{std::vector<DetectedKeypoint>(view.keypoints.size()), 1.0};
        for (size_t k = 0; k < view.keypoints.size(); ++k) {
          const TruthKeypoint& t = view.keypoints[k];
          // Draw for every keypoint so that one keypoint's noise does not depend on another's
          // visibility.
          const double dx = noise.sigma_px * standard_normal(rng);
          const double dy = noise.sigma_px * standard_normal(rng);
          if (!t.known || t.visibility == VisibilityLabel::out_of_frame) continue;
          person.keypoints[k] = {t.pixel.x() + dx, t.pixel.y() + dy, 1.0};
        }
        out.at(f, c).push_back(std::move(person));
      }
    }
  }
  return out;
}

}  // namespace simcap
