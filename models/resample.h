// Resampling a Motion to another frame rate (the renderer's): slerp between the two nearest
// source frames for joint rotations, linear interpolation for the root position.
#pragma once

#include "models/motion.h"

namespace simcap {

// Frames at t = i / fps for every t within the source's duration (the last source frame's
// time included when it falls on the new grid). Throws Error for fps <= 0 or an empty motion.
Motion resample_motion(const Motion& motion, double fps);

}  // namespace simcap
