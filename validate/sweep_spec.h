// A stress sweep file (YAML): one closed-loop configuration (scene, frames, tracker options) and
// the parameters to vary, expanded into the configurations of every point of the sweep.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace simcap {

// One closed-loop run, in the terms of the command line: the apps layer maps it onto the
// renderer's and tracker's options (so that this library depends on neither).
struct LoopConfig {
  std::filesystem::path scene;
  int frames = -1;  // -1: the scene's own length
  std::optional<std::uint64_t> seed;
  std::filesystem::path motion;              // empty: the scene's motion
  std::vector<std::string> scene_overrides;  // "key.path=value", as `--set`
  // Tracker option name (method, silhouettes, init, voxel_m, ...) and value text, in file order;
  // a later entry for the same name wins.
  std::vector<std::pair<std::string, std::string>> track_options;
  double failure_threshold_mm = 100.0;
};

// What one point of an axis changes: `key` is "scene", "frames", "seed", "motion",
// "track.<option>" or a scene key path ("rig.count"); `value` is the YAML scalar's text.
struct SweepSetting {
  std::string key, value;
  int line = 0;  // in the sweep file, for error messages
};

struct SweepAxis {
  std::string name;                                 // table column
  std::vector<std::string> labels;                  // one per point of the axis
  std::vector<std::vector<SweepSetting>> settings;  // one list per point of the axis
  bool numeric() const;  // every label is a number (the plot then has a numeric x axis)
};

struct SweepSpec {
  std::filesystem::path file;
  std::string title;
  LoopConfig base;
  std::vector<SweepAxis> axes;
};

struct SweepPoint {
  std::vector<std::string> labels;  // one per axis
  LoopConfig config;
};

// Points one sweep may have (each renders, tracks and validates; 10000 is days of work).
inline constexpr std::size_t kMaxSweepPoints = 10'000;

// Reads a sweep file. Paths in it are relative to its folder. Errors name the file, line and key.
//
//   title: Accuracy against the number of cameras
//   scene: ../scenes/studio4.yaml
//   frames: 90
//   seed: 1
//   set: {rig.radius: 3.5}                    # fixed scene overrides
//   track: {method: moschini, silhouettes: gt, init: gt}
//   failure_threshold_mm: 100
//   vary:
//     - parameter: rig.count                  # one parameter and its values, or
//       values: [2, 3, 4, 6, 8]
//     - name: silhouettes                     # labelled cases that set several keys each
//       cases:
//         - {label: gt, track.silhouettes: gt}
//         - {label: bgsub, track.silhouettes: bgsub}
SweepSpec load_sweep(const std::filesystem::path& file);

// Every combination of the axes' points (the last axis varies fastest), base settings first.
std::vector<SweepPoint> sweep_points(const SweepSpec& spec);

}  // namespace simcap
