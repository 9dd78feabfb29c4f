// Moschini's extended Kalman filter (§5.1.3, §5.2, Alg. 3) over the 23-parameter body state (34
// with the URDF joint set):
// a random walk (A = I) corrected by the 15 reference points the articulated ICP measured.
#pragma once

#include <Eigen/Core>
#include <array>

#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {

// Standard deviations that set P0, Q (per frame) and R. The defaults were chosen on rendered
// walking and mocap sequences at 30 frames/s: Q lets a limb turn ~15 degrees per frame, R is
// the scatter of ICP's reference points around the truth (larger at the chain ends).
struct FilterNoise {
  double initial_position_m = 0.02;
  double initial_rotation_rad = 0.05;
  double initial_angle_rad = 0.10;
  double position_m = 0.04;    // torso translation per frame
  double rotation_rad = 0.10;  // torso rotation per frame
  // Per JointAngle: neck, shoulders, elbows, hips, knees, hip twists, spine, ankles, wrists.
  std::array<double, kMaxAngles> angle_rad = {0.15, 0.15, 0.25, 0.25, 0.25, 0.25, 0.30, 0.30, 0.30,
                                              0.30, 0.20, 0.20, 0.20, 0.20, 0.30, 0.30, 0.20, 0.20,
                                              0.05, 0.05, 0.05, 0.30, 0.30, 0.30, 0.30, 0.30, 0.30};
  std::array<double, kReferencePointCount> measurement_m = {0.015, 0.025, 0.02,  0.02,  0.02,
                                                            0.02,  0.02,  0.025, 0.025, 0.025,
                                                            0.025, 0.03,  0.03,  0.03,  0.03};
  int iterations = 2;  // iterated EKF: Gauss-Newton steps of the correction
};

// The state is x = [t0 ω0 θ0 θ1 ... θn] (eq. 5.47): 23 parameters for Moschini's joint set, 34
// with the URDF's hip twists, spine, ankles and wrists.
class PoseFilter {
 public:
  static constexpr int kMeasurementSize = 3 * kReferencePointCount;
  using State = Eigen::VectorXd;
  using Covariance = Eigen::MatrixXd;
  using Measurement = Eigen::Matrix<double, kMeasurementSize, 1>;
  using Jacobian = Eigen::Matrix<double, kMeasurementSize, Eigen::Dynamic>;

  PoseFilter(const StickModel& model, const FilterNoise& noise = {});
  int state_size() const { return static_cast<int>(x_.size()); }

  // Starts from `pose` with covariance P0.
  void reset(const StickPose& pose);
  // x⁻ = x, P⁻ = P + Q (Table 5.5 with A = I and no control input).
  void predict();
  // Table 5.7 with H = ∂h/∂x at the current estimate; angles are then held in their limits.
  void correct(const std::array<Eigen::Vector3d, kReferencePointCount>& points);

  StickPose pose() const { return pose_of(x_); }
  const State& state() const { return x_; }

  // The torso orientation is R0 = exp([θ0 ω0]x) R_ref. Moschini's axis-angle (ω0, θ0) has a
  // redundant scale and is singular at θ0 = 0 (the upright, +Z-facing pose), so ω0 θ0 is kept
  // a small rotation vector relative to a reference R_ref that absorbs it after every
  // correction (multiplicative EKF), with θ0 held at 1: its variance is zero.
  StickPose pose_of(const State& x) const;
  // h(x): the 15 reference points (Table 5.2), and its analytic Jacobian.
  Measurement measure(const State& x) const;
  Jacobian jacobian(const State& x) const;

 private:
  const StickModel* model_;
  FilterNoise noise_;
  Eigen::Matrix3d reference_ = Eigen::Matrix3d::Identity();
  State x_;
  Covariance P_, Q_, P0_;
  Eigen::Matrix<double, kMeasurementSize, kMeasurementSize> R_;
};

}  // namespace simcap::tracker
