// A motion: poses of one skeleton sampled at a fixed frame rate. Importers (BVH, procedural)
// produce it; the renderer, SIK and the trackers' ground truth consume it.
#pragma once

#include <string>
#include <vector>

#include "models/pose.h"

namespace simcap {

// What a stretch of a motion means, when its generator knows (the gesture corpus): a dynamic
// gesture of one limb ("7" drawn by the right hand) or a static pose it holds ("up").
struct MotionLabel {
  double start_s = 0, end_s = 0;  // motion time, inclusive
  std::string limb;               // "l_hand" or "r_hand"
  std::string kind;               // "dynamic" or "static"
  std::string label;
};

struct Motion {
  double fps = 30.0;
  std::vector<Pose> frames;         // poses of the skeleton the motion was made for
  std::vector<MotionLabel> labels;  // in start order

  double duration_s() const { return frames.empty() ? 0.0 : (frames.size() - 1) / fps; }
};

}  // namespace simcap
