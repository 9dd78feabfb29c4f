// Unzueta's pelvis orientation from end-effectors (thesis §4.2): Y from pelvis to head, X a
// weighted mean of the right-to-left wrist and ankle vectors and the previous X, Z = X x Y.
#pragma once

#include <Eigen/Geometry>

#include "tracker/unzueta/sik_body.h"

namespace simcap {

// The thesis' weights m1, m2, m3: (1, 1, 0) for Boxing and Jump Kick, (0.1, 0.1, 1) for the
// walking in Playground, where the previous X steadies the torso's axial rotation.
struct SikPelvisWeights {
  double wrists = 1.0;
  double ankles = 1.0;
  double previous = 0.0;
};

class SikPelvisEstimator {
 public:
  explicit SikPelvisEstimator(SikPelvisWeights weights = {}) : weights_(weights) {}

  // Columns X, Y, Z of the estimated pelvis frame (a rotation matrix); remembers X for the next
  // frame. Degenerate input (coincident points) keeps the previous frame's axes.
  Eigen::Matrix3d estimate(const SikTargets& targets);
  void reset() { has_previous_ = false; }

 private:
  SikPelvisWeights weights_;
  Eigen::Matrix3d previous_ = Eigen::Matrix3d::Identity();
  bool has_previous_ = false;
};

}  // namespace simcap
