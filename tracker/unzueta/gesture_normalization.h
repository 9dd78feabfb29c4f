// Gesture normalisation (Unzueta 2009 §5.2): a spotted path resampled to a fixed number of states
// by a cubic spline whose end slopes are the path's first differences (eq. 14), then translated
// and scaled into [0, size] so that performances of other speeds, sizes and bodies compare.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace simcap::tracker {

// The clamped cubic spline through samples[i] at t = i (i = 0..k-1, k >= 2; one row per sample,
// one column per feature), with end derivatives samples[1] - samples[0] and
// samples[k-1] - samples[k-2], evaluated at `count` evenly spaced t from 0 to k-1.
Eigen::MatrixXd resample_clamped_spline(const Eigen::MatrixXd& samples, int count);

// The path resampled to `states` points, moved so that each coordinate's minimum is 0 and scaled
// by one factor so that the largest coordinate range is `size` (Table 12: 30 states, 50), as
// one vector (x0, y0, z0, x1, ...). A path that does not move stays at 0.
Eigen::VectorXd normalize_gesture(const std::vector<Eigen::Vector3d>& path, int states = 30,
                                  double size = 50.0);

}  // namespace simcap::tracker
