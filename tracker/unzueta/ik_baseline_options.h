// What the CCD and DLS baselines of Unzueta's Table 10 share: SIK's pelvis estimate, the joint
// limits and the thesis' stopping rule for an iterative solver.
#pragma once

#include "tracker/unzueta/sik_pelvis.h"

namespace simcap {

struct IkBaselineOptions {
  SikPelvisWeights pelvis_weights;
  bool limits = true;
  // The thesis' stopping rule: every end-effector within 1 cm, or less than 1 mm gained by an
  // iteration (a CCD sweep), or 20 iterations.
  double tolerance = 0.01;
  double min_improvement = 0.001;
  int max_iterations = 20;
};

}  // namespace simcap
