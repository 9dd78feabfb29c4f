// rig.jitter: every camera of a rig moved and turned by a small random amount, so that a
// collection of sequences does not see the room from exactly the same poses.
#pragma once

#include <cstdint>
#include <string>

#include "core/camera.h"

namespace simcap {

struct CameraJitter {
  double position_m = 0;    // each coordinate of the centre moves uniformly in [-p, p]
  double rotation_deg = 0;  // a turn uniform in [0, r] degrees about a uniform random axis
  std::uint64_t seed = 1;
  bool any() const { return position_m > 0 || rotation_deg > 0; }
};

// `camera` jittered by amounts drawn from (jitter.seed, camera.name) alone, so a camera's pose
// does not depend on the other cameras of the rig. The turn is about the camera's centre, its
// axis in the camera's frame: R' = AngleAxis(angle, axis) * R. Intrinsics are unchanged.
Camera jittered(const Camera& camera, const CameraJitter& jitter);

}  // namespace simcap
