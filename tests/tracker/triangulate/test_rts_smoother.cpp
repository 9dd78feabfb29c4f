// The Kalman/RTS smoother against the batch solution it must equal (the Gaussian model's MAP
// over all frames at once, solved densely), and its maximum-likelihood process noise against
// signals whose speed is known.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "tracker/triangulate/rts_smoother.h"

namespace simcap::tracker {
namespace {

using Measurements = std::vector<std::optional<PointMeasurement>>;

// min over all states s_k = (p_k, v_k) of the prior on s_first, the process terms
// (s_{k+1} − F s_k)ᵀ Q⁻¹ (…) and the measurement terms (p_k − z_k)ᵀ R_k⁻¹ (…).
std::vector<Eigen::Vector3d> batch_map(const Measurements& z, double dt, double q) {
  const int n = static_cast<int>(z.size());
  int first = 0;
  while (!z[first]) ++first;
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(6 * n, 6 * n);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(6 * n);
  Eigen::Matrix<double, 6, 6> f = Eigen::Matrix<double, 6, 6>::Identity(), noise;
  f.topRightCorner<3, 3>() = dt * Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d i3 = Eigen::Matrix3d::Identity();
  noise << q * dt * dt * dt / 3 * i3, q * dt * dt / 2 * i3, q * dt * dt / 2 * i3, q * dt * i3;
  const Eigen::Matrix<double, 6, 6> w = noise.inverse();
  for (int k = 0; k + 1 < n; ++k) {
    Eigen::Matrix<double, 6, 12> d;
    d << -f, Eigen::Matrix<double, 6, 6>::Identity();
    h.block<12, 12>(6 * k, 6 * k) += d.transpose() * w * d;
  }
  for (int k = 0; k < n; ++k) {
    if (!z[k]) continue;
    const Eigen::Matrix3d r = z[k]->covariance.inverse();
    h.block<3, 3>(6 * k, 6 * k) += r;
    g.segment<3>(6 * k) += r * z[k]->position;
  }
  h.block<3, 3>(6 * first + 3, 6 * first + 3) += i3 / 100.0;  // the velocity prior, (10 m/s)²
  const Eigen::VectorXd s = h.ldlt().solve(g);
  std::vector<Eigen::Vector3d> out;
  for (int k = 0; k < n; ++k) out.push_back(s.segment<3>(6 * k));
  return out;
}

Measurements noisy_sine(double amplitude, double hz, double noise_m, int frames, double fps,
                        unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_m);
  Measurements z(frames);
  for (int k = 0; k < frames; ++k) {
    const double t = k / fps;
    const Eigen::Vector3d truth(amplitude * std::sin(2 * std::numbers::pi * hz * t), 1.0, 0.5 * t);
    z[k] = PointMeasurement{truth + Eigen::Vector3d(noise(rng), noise(rng), noise(rng)),
                            noise_m * noise_m * Eigen::Matrix3d::Identity()};
  }
  return z;
}

TEST(RtsSmoother, EqualsTheBatchSolution) {
  Measurements z = noisy_sine(0.05, 2.0, 0.01, 25, 30.0, 3);
  z[0].reset();  // a head, an interior gap and a correlated covariance
  z[10].reset();
  z[11].reset();
  z[5]->covariance << 2e-4, 5e-5, 0, 5e-5, 1e-4, 2e-5, 0, 2e-5, 3e-4;
  for (const double q : {0.01, 1.0, 50.0}) {
    const SmoothedTrack t = rts_smooth(z, 1 / 30.0, q);
    const std::vector<Eigen::Vector3d> batch = batch_map(z, 1 / 30.0, q);
    ASSERT_EQ(t.points.size(), z.size());
    for (size_t k = 1; k < z.size(); ++k) {
      EXPECT_LT((t.points[k].position - batch[k]).norm(), 1e-9) << "q " << q << " frame " << k;
    }
  }
}

TEST(RtsSmoother, ConstantVelocityPassesThroughExactly) {
  Measurements z(20);
  for (int k = 0; k < 20; ++k) {
    z[k] = PointMeasurement{Eigen::Vector3d(0.1 * k, -0.05 * k, 2.0),
                            1e-4 * Eigen::Matrix3d::Identity()};
  }
  const SmoothedTrack t = rts_smooth_ml(z, 0.1);
  for (int k = 0; k < 20; ++k) {
    EXPECT_LT((t.points[k].position - z[k]->position).norm(), 1e-6);
  }
}

TEST(RtsSmoother, LikelihoodPicksMoreProcessNoiseForFasterMotion) {
  const double slow =
      rts_smooth_ml(noisy_sine(0.03, 0.5, 0.01, 120, 30.0, 1), 1 / 30.0).acceleration_psd;
  const double fast =
      rts_smooth_ml(noisy_sine(0.03, 3.0, 0.01, 120, 30.0, 1), 1 / 30.0).acceleration_psd;
  EXPECT_GT(fast, 10 * slow);
  // A 3 Hz sine of 3 cm under 1 cm noise is followed, not flattened.
  const Measurements z = noisy_sine(0.03, 3.0, 0.01, 120, 30.0, 2);
  const SmoothedTrack t = rts_smooth_ml(z, 1 / 30.0);
  double err = 0;
  for (int k = 0; k < 120; ++k) {
    err +=
        std::abs(t.points[k].position.x() - 0.03 * std::sin(2 * std::numbers::pi * 3.0 * k / 30.0));
  }
  EXPECT_LT(err / 120, 0.008);
}

}  // namespace
}  // namespace simcap::tracker
