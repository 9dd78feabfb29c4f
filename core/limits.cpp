#include "core/limits.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace simcap::limits {

int frames_within(double duration_s, double fps, long joints, std::string_view what) {
  const double frames = std::floor(duration_s * fps + 1e-6) + 1;
  if (!(frames <= kMaxFrames)) {
    throw Error(std::string(what) + ": " + std::to_string(duration_s) + " s at " +
                std::to_string(fps) + " frames/s is more than simcap's largest frame count, " +
                std::to_string(kMaxFrames));
  }
  if (frames * static_cast<double>(joints) > static_cast<double>(kMaxPoseSamples)) {
    throw Error(std::string(what) + ": " + std::to_string(static_cast<long>(frames)) +
                " frames of " + std::to_string(joints) +
                " joints are more joint rotations than simcap keeps in memory, " +
                std::to_string(kMaxPoseSamples));
  }
  return static_cast<int>(frames);
}

}  // namespace simcap::limits
