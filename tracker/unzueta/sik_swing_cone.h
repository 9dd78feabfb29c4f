// The swing limit of a ball joint in SIK (Unzueta 2009 §4.5): the largest swing psi as a cubic
// spline of the circumduction angle theta through a few anatomical ranges, closed by eq. 10.
#pragma once

#include <utility>
#include <vector>

namespace simcap {

class SwingCone {
 public:
  // `points` are (theta, psi_max) in radians with theta strictly increasing from -pi to +pi; the
  // first and last psi must be equal (they are the same direction). Throws Error otherwise.
  explicit SwingCone(std::vector<std::pair<double, double>> points);

  // psi_max at circumduction angle `theta` (any real; wrapped into [-pi, pi)).
  double max_swing(double theta) const;

 private:
  std::vector<double> theta_, psi_;
  std::vector<double> second_;  // spline second derivatives at the knots
};

}  // namespace simcap
