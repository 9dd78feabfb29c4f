// Gesture spotting by kinetic pseudo-energy history (Unzueta 2009 §5.1): a limb is gesturing
// while the mean of its last n pseudo-energies psE = |v|^2 / 2 is above a threshold; the start
// and end found that way lag the motion by a delay that Algorithm 14 measures at the start.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace simcap::tracker {

struct SpottingParams {
  int history = 10;  // n, frames (Table 12)
  // On the mean pseudo-energy, (m/s)^2 / 2: 0.18 is a mean hand speed of 0.6 m/s. The thesis'
  // 2.5 is in its own pixel units; simcap's signals are metres in the pelvis frame.
  double threshold = 0.18;
  // Shorter spotted stretches are dropped (simcap's; not in the thesis): 10 frames, the
  // shortest gesture of scenes/gestures.yaml at 30 frames/s.
  int min_frames = 10;
  // A stretch counts only if, somewhere in it, the history's mean without its this many largest
  // values also reaches the threshold (simcap's; 0 is the thesis): a tracked hand's depth that
  // jumps between two surfaces in one frame (a hand pointing at the camera read on its forearm,
  // then on itself) is one huge psE, whose tenth alone crosses the threshold for n frames; a
  // gesture's energy lasts. The stretch's ends are the thesis' either way.
  int drop_largest = 1;
};

// psE[i] = |x[i] - x[i-1]|^2 fps^2 / 2; psE[0] = 0.
std::vector<double> kinetic_pseudo_energy(const std::vector<Eigen::Vector3d>& x, double fps);

// mean[t]: the mean of psE over the history window [t-n+1, t] (fewer values at the start), the
// quantity compared with the threshold.
std::vector<double> history_mean(const std::vector<double>& psE, int history);

// Algorithm 14 at frame t: t minus the last frame of the history window [t-n+1, t] whose psE
// is below the threshold (0 when none is).
int spotting_delay(const std::vector<double>& psE, int t, int history, double threshold);

struct SpottedStretch {
  int first = 0, last = 0;  // indices into the signal, inclusive
};

// The stretches during which the mean pseudo-energy history is at or above the threshold (and
// confirmed without its `drop_largest` largest values), both ends
// moved back by the delay Algorithm 14 gives where the stretch is first detected. A stretch still
// open at the end of the signal ends at its last index.
std::vector<SpottedStretch> spot_gestures(const std::vector<double>& psE,
                                          const SpottingParams& params);

}  // namespace simcap::tracker
