// Unzueta's pelvis orientation from end-effectors (thesis §4.2): Y from pelvis to head, X a
// weighted mean of the right-to-left wrist and ankle vectors and the previous X, Z = X x Y.
#pragma once

#include <Eigen/Geometry>
#include <deque>

#include "tracker/unzueta/sik_body.h"

namespace simcap {

// The thesis' weights m1, m2, m3: (1, 1, 0) for Boxing and Jump Kick, (0.1, 0.1, 1) for the
// walking in Playground, where the previous X steadies the torso's axial rotation. `travel` (not
// the thesis') weighs the X that faces the pelvis' recent horizontal travel, times its agreement
// with the limbs' X (none for side or backward steps), so walking turns the pelvis toward its path.
struct SikPelvisWeights {
  double wrists = 1.0;
  double ankles = 1.0;
  double previous = 0.0;
  double travel = 0.0;
};

class SikPelvisEstimator {
 public:
  explicit SikPelvisEstimator(SikPelvisWeights weights = {}) : weights_(weights) {}

  // Columns X, Y, Z of the estimated pelvis frame (a rotation matrix); remembers X for the next
  // frame. Degenerate input (coincident points) keeps the previous frame's axes.
  Eigen::Matrix3d estimate(const SikTargets& targets);
  void reset() {
    has_previous_ = false;
    trail_.clear();
  }

  // The travel cue needs the pelvis to have moved this far (m) across the plane normal to Y
  // within the last kTrailFrames frames: a stride, beyond the sway of standing.
  static constexpr double kTravelDistance = 0.3;
  static constexpr size_t kTrailFrames = 240;

 private:
  // Unit direction of the pelvis' recent travel across the plane normal to y; zero when it has
  // not moved kTravelDistance.
  Eigen::Vector3d travel(const Eigen::Vector3d& pelvis, const Eigen::Vector3d& y);

  SikPelvisWeights weights_;
  Eigen::Matrix3d previous_ = Eigen::Matrix3d::Identity();
  bool has_previous_ = false;
  std::deque<Eigen::Vector3d> trail_;  // past pelvis positions, newest last
};

}  // namespace simcap
