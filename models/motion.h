// A motion: poses of one skeleton sampled at a fixed frame rate. Importers (BVH, procedural)
// produce it; the renderer, SIK and the trackers' ground truth consume it.
#pragma once

#include <vector>

#include "models/pose.h"

namespace simcap {

struct Motion {
  double fps = 30.0;
  std::vector<Pose> frames;  // poses of the skeleton the motion was made for

  double duration_s() const { return frames.empty() ? 0.0 : (frames.size() - 1) / fps; }
};

}  // namespace simcap
