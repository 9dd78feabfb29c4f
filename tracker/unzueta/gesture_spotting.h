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
  // A stretch whose history mean stays at or above the threshold for fewer frames is dropped
  // (simcap's; not in the thesis): 10 frames, the shortest gesture of scenes/gestures.yaml at 30
  // frames/s. Counted on the history itself, not on the stretch its delays give: with
  // `delay_at_end` the stretch is the part of a gesture whose psE is above the threshold, a few
  // frames shorter than the gesture by its ease-in and ease-out.
  int min_frames = 10;
  // A stretch counts only if, somewhere in it, the history's mean without its this many largest
  // values also reaches the threshold (simcap's; 0 is the thesis): a tracked hand's depth that
  // jumps between two surfaces in one frame (a hand pointing at the camera read on its forearm,
  // then on itself) is one huge psE, whose tenth alone crosses the threshold for n frames; a
  // gesture's energy lasts. It does not move the stretch's ends.
  int drop_largest = 1;
  // Algorithm 14 measured again where the stretch ends (simcap's; false is the thesis, which
  // moves the end back by the delay measured at the start): the end is the last frame whose psE
  // is at or above the threshold when the history falls below it. A stroke starts slowly and stops
  // sharply (or the reverse), so the history's lag differs at its two ends; the start's delay put
  // the ends of the corpus' short digits 3-5 frames late, which alone fails their temporal IoU.
  bool delay_at_end = true;
  // Each velocity coordinate of the path is the median of this many frames around it before
  // the psE is taken (simcap's; 1 is the thesis). A tracked point that jumps (a depth read on
  // another surface, a restarted track, the step from the calibration posture to the first
  // tracked frame) moves in one or two frames and is not kinetic energy; a hand's motion lasts.
  int velocity_median = 5;
};

// The path rebuilt from its first point and its velocities x[i] - x[i-1], each coordinate of
// each velocity replaced by the median of the `frames` velocities centred on it (edges
// repeated; the first velocity is 0): a displacement made in fewer than (frames + 1) / 2 of the
// frames around it (a step that stays, a spike out and back) is dropped, a motion that lasts
// that long is kept. frames = 1 returns x.
std::vector<Eigen::Vector3d> median_velocity_path(const std::vector<Eigen::Vector3d>& x,
                                                  int frames);

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
// confirmed without its `drop_largest` largest values), for at least `min_frames` frames; the
// start moved back by the delay Algorithm 14 gives where the stretch is first detected, the end
// by that delay too or (`delay_at_end`) by the one measured where the history falls below. A
// stretch still open at the end of the signal ends at its last index.
std::vector<SpottedStretch> spot_gestures(const std::vector<double>& psE,
                                          const SpottingParams& params);

// The stretch widened on each side, not past `lo` and `hi`, over the frames whose psE is at least
// `fraction`^2 of its largest psE inside the stretch: the motion from where its speed first
// reaches `fraction` of its peak speed to where it falls below it again; 0 keeps the stretch.
SpottedStretch widen_to_motion(const std::vector<double>& psE, SpottedStretch s, int lo, int hi,
                               double fraction);

}  // namespace simcap::tracker
