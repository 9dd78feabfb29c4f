// The registration of thesis chapter 3, without the particle filter: Nelder-Mead from a start
// pose on the region energy, then on the edge energy from the region step's final simplex (or
// from a small fresh simplex when the region step converged to a point).
#pragma once

#include "tracker/gomez/pose_scorer.h"

namespace simcap::tracker::gomez {

struct RegistrationOptions {
  int evaluations = 500;           // per frame, both steps (the thesis's real-time budget)
  double region_share = 0.5;       // of the evaluations spent on regions (thesis Table 3-2: 50%)
  double simplex_size = 1.5;       // initial simplex, in DOF steps (thesis §2.4.4.4: 1.5 to 2)
  double edge_simplex_size = 0.3;  // the fresh simplex of the edge step, in DOF steps
};

struct Registered {
  State x;
  Score score;
  int evaluations = 0;
};

// `region_only` skips the edge step (the upright start has no edges it can trust yet).
Registered register_pose(const PoseScorer& scorer, const FrameCues& cues, const State& start,
                         const RegistrationOptions& options, bool region_only = false);

}  // namespace simcap::tracker::gomez
