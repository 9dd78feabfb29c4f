// The error measures of pose estimation, each a small pure function so that it can be checked
// against hand-computed values: joint distances, Procrustes alignment, PCK, RMSE, rotation angle.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace simcap {

// Euclidean distance of every column of `estimate` to the same column of `truth` (3 x J each).
Eigen::VectorXd joint_distances(const Eigen::Matrix3Xd& truth, const Eigen::Matrix3Xd& estimate);

// `estimate` moved by the similarity transform (rotation, uniform scale, translation) that best
// fits it to `truth` in the least-squares sense (Umeyama 1991, via Eigen's SVD). The distances
// of the result to `truth` are the per-joint errors of PA-MPJPE.
Eigen::Matrix3Xd procrustes_aligned(const Eigen::Matrix3Xd& truth,
                                    const Eigen::Matrix3Xd& estimate);

// Fraction of `errors` at or below `threshold` (Percentage of Correct Keypoints, as a fraction).
double pck(const std::vector<double>& errors, double threshold);

// sqrt(sum(e^2) / M): Moschini's per-point RMSE (thesis eq. 7.3) over M samples.
double root_mean_square(const std::vector<double>& errors);

double mean_value(const std::vector<double>& values);

// Angle of the rotation that takes `a` to `b`: arccos((tr(R_a R_b^T) - 1) / 2) (Moschini eq. 7.1),
// computed from the quaternions so that it stays accurate near zero.
double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

// A run of consecutive frames whose error is above the failure threshold.
struct FailureEpisode {
  int first_frame = 0;     // first frame above the threshold
  int frames = 0;          // frames until the error is back at or below it
  bool recovered = false;  // false when the sequence ends before the error comes back down
};

// Episodes of `per_frame_error` (frame numbers in `frames`, ascending) above `threshold`.
std::vector<FailureEpisode> failure_episodes(const std::vector<int>& frames,
                                             const std::vector<double>& per_frame_error,
                                             double threshold);

}  // namespace simcap
