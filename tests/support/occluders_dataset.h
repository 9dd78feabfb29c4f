// A small rendered dataset shared by one test program: the occluders scene (pillars and a
// table hide limbs, so every visibility label occurs) at 320x240, 4 frames from frame 100.
#pragma once

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "tests/support/temp_dir.h"

namespace simcap::testing {

inline constexpr int kOccludersFrames = 4;

// Rendered by the first call, removed when the program exits; throws when rendering fails.
inline std::filesystem::path occluders_dataset() {
  static const std::unique_ptr<TempDir> dir = [] {
    auto d = std::make_unique<TempDir>();
    std::string log;
    if (run_simcap("render " SIMCAP_SOURCE_DIR "/scenes/occluders.yaml -o " +
                       (d->path() / "d").string() +
                       " -q --set 'rig.resolution=[320,240]' --set render.first_frame=100 "
                       "--frames " +
                       std::to_string(kOccludersFrames),
                   &log) != 0) {
      throw std::runtime_error("rendering the occluders dataset failed:\n" + log);
    }
    return d;
  }();
  return dir->path() / "d";
}

}  // namespace simcap::testing
