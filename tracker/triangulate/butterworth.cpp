#include "tracker/triangulate/butterworth.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace simcap::tracker {
namespace {

// Direct form II transposed, started in the steady state of a constant input x[0].
void run(const Biquad& f, std::vector<double>& x) {
  if (x.empty()) return;
  double z1 = (1.0 - f.b0) * x[0], z2 = (f.b2 - f.a2) * x[0];
  for (double& v : x) {
    const double y = f.b0 * v + z1;
    z1 = f.b1 * v - f.a1 * y + z2;
    z2 = f.b2 * v - f.a2 * y;
    v = y;
  }
}

}  // namespace

Biquad butterworth_lowpass(double cutoff_hz, double rate_hz) {
  if (!(cutoff_hz > 0 && cutoff_hz < rate_hz / 2)) {
    throw Error("Butterworth cut-off " + std::to_string(cutoff_hz) +
                " Hz: expected more than 0 and less than half the frame rate (" +
                std::to_string(rate_hz / 2) + " Hz)");
  }
  const double k = std::tan(std::numbers::pi * cutoff_hz / rate_hz);
  const double q = std::numbers::sqrt2;
  const double norm = 1.0 / (1.0 + q * k + k * k);
  Biquad f;
  f.b0 = k * k * norm;
  f.b1 = 2.0 * f.b0;
  f.b2 = f.b0;
  f.a1 = 2.0 * (k * k - 1.0) * norm;
  f.a2 = (1.0 - q * k + k * k) * norm;
  return f;
}

std::vector<double> filtfilt(const Biquad& f, std::span<const double> signal) {
  const size_t n = signal.size();
  if (n < 2) return {signal.begin(), signal.end()};
  // scipy's default padlen: 3 * max(len(a), len(b)) = 9 for a biquad, capped by the signal.
  const size_t pad = std::min<size_t>(9, n - 1);
  std::vector<double> x;
  x.reserve(n + 2 * pad);
  for (size_t i = pad; i >= 1; --i) x.push_back(2.0 * signal[0] - signal[i]);
  x.insert(x.end(), signal.begin(), signal.end());
  for (size_t i = 1; i <= pad; ++i) x.push_back(2.0 * signal[n - 1] - signal[n - 1 - i]);
  run(f, x);
  std::reverse(x.begin(), x.end());
  run(f, x);
  std::reverse(x.begin(), x.end());
  return {x.begin() + static_cast<long>(pad), x.begin() + static_cast<long>(pad + n)};
}

}  // namespace simcap::tracker
