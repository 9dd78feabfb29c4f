// The zero-phase Butterworth low-pass against scipy.signal.butter's published coefficients and
// the analytic response: unit gain at DC, exactly one half (|H|² = 1/2) at the cut-off.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "tracker/triangulate/butterworth.h"

namespace simcap::tracker {
namespace {

TEST(Butterworth, MatchesScipyCoefficients) {
  // scipy.signal.butter(2, 6 / 15): b = [0.20657208, 0.41314417, 0.20657208],
  // a = [1, -0.36952738, 0.19581571] (Pose2Sim's 6 Hz at 30 frames/s).
  const Biquad f = butterworth_lowpass(6.0, 30.0);
  EXPECT_NEAR(f.b0, 0.20657208, 1e-8);
  EXPECT_NEAR(f.b1, 0.41314417, 1e-8);
  EXPECT_NEAR(f.b2, 0.20657208, 1e-8);
  EXPECT_NEAR(f.a1, -0.36952738, 1e-8);
  EXPECT_NEAR(f.a2, 0.19581571, 1e-8);
  EXPECT_THROW(butterworth_lowpass(15.0, 30.0), std::exception);
  EXPECT_THROW(butterworth_lowpass(0.0, 30.0), std::exception);
}

TEST(Butterworth, ZeroPhaseGainIsHalfAtTheCutOff) {
  const double rate = 100.0, cutoff = 5.0;
  const Biquad f = butterworth_lowpass(cutoff, rate);
  const int n = 2000;
  std::vector<double> dc(n, 1.7), at_cutoff(n), slow(n);
  for (int i = 0; i < n; ++i) {
    at_cutoff[i] = std::sin(2 * std::numbers::pi * cutoff * i / rate);
    slow[i] = std::sin(2 * std::numbers::pi * 0.2 * i / rate);
  }
  for (double v : filtfilt(f, dc)) EXPECT_NEAR(v, 1.7, 1e-12);
  const auto y = filtfilt(f, at_cutoff);
  const auto s = filtfilt(f, slow);
  // Away from the ends: the same phase, half the amplitude; a slow signal passes unchanged.
  for (int i = 500; i < 1500; ++i) {
    EXPECT_NEAR(y[i], 0.5 * at_cutoff[i], 1e-3) << i;
    EXPECT_NEAR(s[i], slow[i], 1e-4) << i;
  }
  EXPECT_EQ(filtfilt(f, std::vector<double>{3.0}), std::vector<double>{3.0});
}

}  // namespace
}  // namespace simcap::tracker
