// Test support for the joint refinement: a stick body with typical capsules, and refinement
// options that run to convergence with no priors (priors pull towards a pose on purpose, which
// would bias a test of whether the data alone recover the truth).
#pragma once

#include <algorithm>

#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/pose_refiner.h"

namespace simcap::testing {

// An adult's proportions (BodyDimensions' defaults) and an adult's girths on them.
inline tracker::BodyDimensions capsule_body() {
  return {};
}
inline tracker::BodySurface capsule_surface() {
  return tracker::typical_surface(capsule_body());
}

inline tracker::RefineOptions converging_without_priors(int iterations = 30) {
  tracker::RefineOptions options;
  options.iterations = iterations;
  options.tolerance = 0;
  options.leg_prior_m_per_rad = 0;
  options.motion_prior_m_per_rad = 0;
  return options;
}

// The largest distance between the reference points of two poses.
inline double max_joint_error(const tracker::StickModel& model, const tracker::StickPose& a,
                              const tracker::StickPose& b) {
  const auto pa = model.reference_points(model.geometry(a));
  const auto pb = model.reference_points(model.geometry(b));
  double worst = 0;
  for (int i = 0; i < tracker::kReferencePointCount; ++i)
    worst = std::max(worst, (pa[i] - pb[i]).norm());
  return worst;
}

}  // namespace simcap::testing
