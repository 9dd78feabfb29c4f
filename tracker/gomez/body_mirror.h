// The front/back ambiguity of a silhouette: a full body's state reflected through the vertical
// plane across the camera ray (facing the other way, left and right swapped), the hypothesis
// the particle filter tests now and then.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tracker/gomez/body_dofs.h"

namespace simcap::tracker::gomez {

class BodyMirror {
 public:
  // Pairs each "l_" DOF of `dofs` with its "r_" partner; throws Error for a DOF without one.
  // Keeps a reference to `dofs`.
  explicit BodyMirror(const BodyDofs& dofs);

  // Whether the body has a free root to turn (the upper body's root is held).
  bool available() const { return turn_ >= 0; }
  // `x` reflected through the vertical plane through its root whose normal is the horizontal
  // part of the ray from `camera_centre` to the root: each left DOF takes its right partner's
  // value (and back), rotations about Y and Z change sign (a reflection across the body's
  // sagittal plane), and the heading becomes the reflected one. For a skeleton symmetric about
  // its sagittal plane every joint lands on the reflection of its partner, so the silhouette
  // seen along the ray stays nearly the same (exactly, seen orthographically). Clamped to the
  // box. Not available: `x` unchanged.
  State reflect(const State& x, const Eigen::Vector3d& camera_centre) const;

 private:
  const BodyDofs* dofs_;
  std::vector<int> partner_;  // DOF index of the mirror partner (itself on the midline)
  std::vector<double> sign_;  // +1 for rotations about X and translations, -1 about Y and Z
  int turn_ = -1;             // root_turn's index
};

}  // namespace simcap::tracker::gomez
