#include "models/resample.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/limits.h"

namespace simcap {

Motion resample_motion(const Motion& motion, double fps) {
  if (!(fps > 0) || !std::isfinite(fps)) {
    throw Error("resample: frame rate must be positive, got " + std::to_string(fps));
  }
  if (motion.frames.empty()) throw Error("resample: the motion has no frames");
  if (!(motion.fps > 0)) throw Error("resample: the motion's frame rate is not positive");
  Motion out;
  out.fps = fps;
  const int n_in = static_cast<int>(motion.frames.size());
  const int n_out = limits::frames_within(motion.duration_s(), fps,
                                          static_cast<long>(motion.frames.front().rotations.size()),
                                          "resample: the motion");
  out.frames.reserve(n_out);
  for (int i = 0; i < n_out; ++i) {
    const double u = std::min(i / fps * motion.fps, static_cast<double>(n_in - 1));
    const int i0 = std::min(static_cast<int>(std::floor(u)), std::max(n_in - 2, 0));
    const int i1 = std::min(i0 + 1, n_in - 1);
    const double a = std::clamp(u - i0, 0.0, 1.0);
    const Pose& p0 = motion.frames[i0];
    const Pose& p1 = motion.frames[i1];
    if (p0.rotations.size() != p1.rotations.size()) {
      throw Error("resample: frames " + std::to_string(i0) + " and " + std::to_string(i1) +
                  " have different joint counts");
    }
    Pose p;
    p.root_position = (1 - a) * p0.root_position + a * p1.root_position;
    p.rotations.resize(p0.rotations.size());
    for (size_t j = 0; j < p0.rotations.size(); ++j) {
      p.rotations[j] = p0.rotations[j].slerp(a, p1.rotations[j]).normalized();
    }
    out.frames.push_back(std::move(p));
  }
  return out;
}

}  // namespace simcap
