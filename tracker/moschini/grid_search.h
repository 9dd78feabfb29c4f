// Where a shallow, noisy cost of one parameter is least: evenly spaced evaluations and the
// parabola through the least of them and its neighbours (no derivatives, no unimodality needed).
#pragma once

#include <algorithm>
#include <vector>

namespace simcap::tracker {

// The argument in [lo, hi] at which f is least: f on `evaluations` (>= 3) evenly spaced points,
// then the vertex of the parabola through the least and its two neighbours, kept between them.
// A golden-section search on such a cost follows its noise: --init auto's shoulder height
// (d_s) came out anywhere in a valley 0.2 wide.
template <typename F>
double least_on_grid(F&& f, double lo, double hi, int evaluations) {
  const double step = (hi - lo) / (evaluations - 1);
  std::vector<double> cost(evaluations);
  for (int i = 0; i < evaluations; ++i) cost[i] = f(lo + i * step);
  const int i = std::clamp<int>(std::min_element(cost.begin(), cost.end()) - cost.begin(), 1,
                                evaluations - 2);
  const double curvature = cost[i - 1] - 2 * cost[i] + cost[i + 1];
  const double offset = curvature > 0 ? 0.5 * (cost[i - 1] - cost[i + 1]) / curvature : 0.0;
  return lo + (i + std::clamp(offset, -1.0, 1.0)) * step;
}

}  // namespace simcap::tracker
