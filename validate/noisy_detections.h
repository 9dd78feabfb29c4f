// Detections made from the ground truth with Gaussian pixel noise: a detector whose errors are
// known exactly, for testing triangulation and 2D scoring and for the stress sweeps.
#pragma once

#include <cstdint>

#include "models/detections.h"
#include "validate/keypoint_truth.h"

namespace simcap {

struct TruthNoise {
  double sigma_px = 0;     // standard deviation of each pixel coordinate's noise
  std::uint64_t seed = 1;  // same seed, same dataset => the same detections
};

// One person per actor with pixels in an image (KeypointTruth's `annotated`), score 1: every
// keypoint with ground truth that is not out_of_frame at its true pixel plus independent
// N(0, sigma_px^2) noise in x and y, score 1; the others (no ground truth, out of frame) not
// detected (0, 0, 0). People in actor order.
Detections detections_from_truth(const KeypointTruth& truth, const TruthNoise& noise);

}  // namespace simcap
