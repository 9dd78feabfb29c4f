#include "core/limits.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace simcap::limits {

int frames_within(double duration_s, double fps, std::string_view what) {
  const double frames = std::floor(duration_s * fps + 1e-6) + 1;
  if (!(frames <= kMaxFrames)) {
    throw Error(std::string(what) + ": " + std::to_string(duration_s) + " s at " +
                std::to_string(fps) + " frames/s is more than simcap's largest frame count, " +
                std::to_string(kMaxFrames));
  }
  return static_cast<int>(frames);
}

}  // namespace simcap::limits
