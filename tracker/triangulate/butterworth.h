// Zero-phase Butterworth low-pass of a sampled signal, as Pose2Sim filters triangulated joints
// (scipy.signal.butter + filtfilt): the biquad forward then backward, odd-extended at the ends.
#pragma once

#include <span>
#include <vector>

namespace simcap::tracker {

// Coefficients of the 2nd-order Butterworth low-pass by the bilinear transform with the cut-off
// pre-warped (what scipy.signal.butter(2, cutoff / (rate / 2)) returns), a0 = 1.
struct Biquad {
  double b0 = 1, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
};
// Throws Error unless 0 < cutoff_hz < rate_hz / 2.
Biquad butterworth_lowpass(double cutoff_hz, double rate_hz);

// The filter run forward and backward (no phase lag; the magnitude response squared, i.e. a
// 4th-order roll-off), each pass started in the steady state of its first sample and the signal
// odd-extended by up to 9 samples at both ends, as scipy.signal.filtfilt does by default.
std::vector<double> filtfilt(const Biquad& filter, std::span<const double> signal);

}  // namespace simcap::tracker
