// The common face of the inverse-kinematics solvers compared in Unzueta's Table 10 (SIK and the
// CCD and DLS baselines): six end-effector targets in, a pose of the solver's skeleton out.
#pragma once

#include <string_view>

#include "models/pose.h"
#include "tracker/unzueta/sik_body.h"

namespace simcap {

class IkSolver {
 public:
  virtual ~IkSolver() = default;
  virtual std::string_view name() const = 0;
  virtual const SikBody& body() const = 0;
  // Solves one frame. Frames come in sequence: a solver may start from the previous result.
  virtual const Pose& solve(const SikTargets& targets) = 0;
  // Forgets earlier frames (the next solve starts from the neutral pose).
  virtual void reset() = 0;
};

}  // namespace simcap
