#include "tracker/moschini/ekf.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

namespace simcap::tracker {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return m;
}

// Rodrigues: R = cI + (1 - c) w w^T + s [w]x for the unit axis w and angle |r| (eq. 5.25).
Eigen::Matrix3d exp_so3(const Eigen::Vector3d& r) {
  const double angle = r.norm();
  if (angle < 1e-12) return Eigen::Matrix3d::Identity() + skew(r);
  return Eigen::AngleAxisd(angle, r / angle).toRotationMatrix();
}

// Left Jacobian of SO(3): exp([r + δ]x) ≈ exp([J_l(r) δ]x) exp([r]x).
Eigen::Matrix3d left_jacobian(const Eigen::Vector3d& r) {
  const double a = r.norm();
  const Eigen::Matrix3d K = skew(r);
  if (a < 1e-6) return Eigen::Matrix3d::Identity() + 0.5 * K + K * K / 6.0;
  return Eigen::Matrix3d::Identity() + (1 - std::cos(a)) / (a * a) * K +
         (a - std::sin(a)) / (a * a * a) * K * K;
}

constexpr int kT = 0, kOmega = 3, kTheta0 = 6, kAngles = 7;

}  // namespace

PoseFilter::PoseFilter(const StickModel& model, const FilterNoise& noise)
    : model_(&model), noise_(noise) {
  const int n = 7 + model.angle_count();
  x_ = State::Zero(n);
  auto fill = [&](Covariance& C, double position, double rotation,
                  const std::array<double, kMaxAngles>& angles) {
    C = Covariance::Zero(n, n);
    for (int i = 0; i < 3; ++i) {
      C(kT + i, kT + i) = position * position;
      C(kOmega + i, kOmega + i) = rotation * rotation;
    }
    for (int k = 0; k < model.angle_count(); ++k) {
      C(kAngles + k, kAngles + k) = angles[k] * angles[k];
    }
  };
  std::array<double, kMaxAngles> initial_angles;
  initial_angles.fill(noise.initial_angle_rad);
  fill(P0_, noise.initial_position_m, noise.initial_rotation_rad, initial_angles);
  fill(Q_, noise.position_m, noise.rotation_rad, noise.angle_rad);
  R_.setZero();
  for (int i = 0; i < kReferencePointCount; ++i) {
    const double v = noise.measurement_m[i] * noise.measurement_m[i];
    R_.block<3, 3>(3 * i, 3 * i) = Eigen::Matrix3d::Identity() * v;
  }
}

void PoseFilter::reset(const StickPose& pose) {
  reference_ = pose.R0;
  x_.setZero();
  x_.segment<3>(kT) = pose.t0;
  x_(kTheta0) = 1.0;
  for (int k = 0; k < model_->angle_count(); ++k) x_(kAngles + k) = pose.theta[k];
  P_ = P0_;
}

StickPose PoseFilter::pose_of(const State& x) const {
  StickPose pose;
  pose.t0 = x.segment<3>(kT);
  pose.R0 = exp_so3(x(kTheta0) * x.segment<3>(kOmega)) * reference_;
  pose.theta.fill(0.0);
  for (int k = 0; k < model_->angle_count(); ++k) pose.theta[k] = x(kAngles + k);
  return pose;
}

PoseFilter::Measurement PoseFilter::measure(const State& x) const {
  const auto p = model_->reference_points(model_->geometry(pose_of(x)));
  Measurement z;
  for (int i = 0; i < kReferencePointCount; ++i) z.segment<3>(3 * i) = p[i];
  return z;
}

PoseFilter::Jacobian PoseFilter::jacobian(const State& x) const {
  const StickPose pose = pose_of(x);
  const StickGeometry g = model_->geometry(pose);
  const auto p = model_->reference_points(g);
  Jacobian H = Jacobian::Zero(kMeasurementSize, x.size());
  const Eigen::Vector3d omega = x.segment<3>(kOmega);
  const double theta0 = x(kTheta0);
  const Eigen::Matrix3d Jl = left_jacobian(theta0 * omega);
  for (int i = 0; i < kReferencePointCount; ++i) {
    // Every point is t0 + exp([r]x) q with r = θ0 ω0, so dp/dr = -[p - t0]x J_l(r).
    const Eigen::Matrix3d dp_dr = -skew(p[i] - pose.t0) * Jl;
    H.block<3, 3>(3 * i, kT).setIdentity();
    H.block<3, 3>(3 * i, kOmega) = dp_dr * theta0;
    H.block<3, 1>(3 * i, kTheta0) = dp_dr * omega;
  }
  H.rightCols(model_->angle_count()) = model_->angle_jacobian(g, p);
  return H;
}

void PoseFilter::predict() {
  P_ += Q_;
}

void PoseFilter::correct(const std::array<Eigen::Vector3d, kReferencePointCount>& points) {
  Measurement z;
  for (int i = 0; i < kReferencePointCount; ++i) z.segment<3>(3 * i) = points[i];
  const State prior = x_;
  State x = x_;
  Eigen::MatrixXd K;
  Jacobian H;
  for (int it = 0; it < std::max(1, noise_.iterations); ++it) {
    H = jacobian(x);
    const Eigen::Matrix<double, kMeasurementSize, kMeasurementSize> S = H * P_ * H.transpose() + R_;
    K = P_ * H.transpose() *
        S.ldlt().solve(Eigen::Matrix<double, kMeasurementSize, kMeasurementSize>::Identity());
    x = prior + K * (z - measure(x) - H * (prior - x));
  }
  P_ = (Covariance::Identity(x.size(), x.size()) - K * H) * P_;
  P_ = 0.5 * (P_ + P_.transpose()).eval();
  // Fold the rotation increment into the reference (the multiplicative reset), then hold the
  // angles in Table 5.1's ranges: the hard constraints.
  reference_ = exp_so3(x(kTheta0) * x.segment<3>(kOmega)) * reference_;
  x.segment<3>(kOmega).setZero();
  const auto& ranges = model_->ranges();
  for (int k = 0; k < model_->angle_count(); ++k) {
    x(kAngles + k) = limit_angle(x(kAngles + k), ranges[k]);
  }
  x_ = x;
}

}  // namespace simcap::tracker
