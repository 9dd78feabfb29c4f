// Test support for the joint refinement: a stick body with capsule radii, and refinement options
// that run to convergence with no priors (priors pull towards a pose on purpose, which would
// bias a test of whether the data alone recover the truth).
#pragma once

#include "tracker/pose_refiner.h"

namespace simcap::testing {

// An adult's proportions (BodyDimensions' defaults) with typical radii and a round torso.
inline tracker::BodyDimensions capsule_body() {
  tracker::BodyDimensions dims;
  dims.radius = {0.13, 0.09, 0.05, 0.04, 0.05, 0.04, 0.075, 0.055, 0.075, 0.055};
  dims.torso_width = dims.radius[tracker::kTorso];
  return dims;
}

inline tracker::RefineOptions converging_without_priors(int iterations = 30) {
  tracker::RefineOptions options;
  options.iterations = iterations;
  options.tolerance = 0;
  options.leg_prior_m_per_rad = 0;
  options.motion_prior_m_per_rad = 0;
  return options;
}

}  // namespace simcap::testing
