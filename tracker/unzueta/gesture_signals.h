// What Unzueta's gesture chapter looks at (§5.3): each hand's path and the full-body pose (head,
// hands and feet) in a frame attached to the pelvis, from any tracker's joints3d.csv.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "core/joint_track.h"

namespace simcap::tracker {

// The limbs that gesture, named as in gt/gestures.csv.
inline const std::array<std::string, 2> kGestureLimbs = {"l_hand", "r_hand"};

struct BodySignals {
  std::vector<int> frames;
  // hand[l][i]: limb l's wrist at frames[i] in the pelvis frame, metres.
  std::array<std::vector<Eigen::Vector3d>, 2> hand;
  // pose[i]: the 15 pose features (head, hands, feet in the pelvis frame), metres.
  std::vector<Eigen::Matrix<double, 15, 1>> pose;
};

// The pelvis frame: origin at humanoid_root, Y up (the world's), X from r_hip to l_hip in the
// horizontal plane, Z = X x Y (forward). Throws Error naming `source` when a needed HE15 joint
// (humanoid_root, skullbase, l/r_hip, l/r_radiocarpal, l/r_talocrural) is missing or NaN.
BodySignals body_signals(const JointTrack& track, const std::string& source);

// Smooths every signal over time by a Gaussian of `sigma` frames (edges repeated; 0: unchanged).
// The thesis' signals are CFOF's Kalman-filtered image tracks; simcap's are 3D joints of a
// tracker that may not filter them, whose frame-to-frame jitter would read as kinetic energy.
void smooth_signals(BodySignals& signals, double sigma);

// One path smoothed the same way.
void smooth_path(std::vector<Eigen::Vector3d>& path, double sigma);

}  // namespace simcap::tracker
