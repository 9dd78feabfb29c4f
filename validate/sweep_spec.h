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

// The 2D detector of a sweep's closed loop (`detector:`), whose keypoints the triangulate
// tracker lifts; its name is checked by the apps layer, which knows the detectors.
struct DetectorConfig {
  std::string name;        // empty: none, the tracker reads the images
  int line = 0;            // of the name in the sweep file
  double noise_px = 2.0;   // truth-noise: standard deviation of each pixel coordinate's noise
  std::uint64_t seed = 1;  // truth-noise: seed of that noise
};

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
  // The sweep file's line of each scene override and tracker option above, in their order, for
  // the errors of the loaders that check them later.
  std::vector<int> scene_override_lines, track_option_lines;
  double failure_threshold_mm = 100.0;
  DetectorConfig detector;
};

// What one point of an axis changes: `key` is "scene", "frames", "seed", "motion",
// "track.<option>", "detector.name|noise_px|seed" or a scene key path ("rig.count"); `value` is the
// YAML scalar's text.
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
//   detector: {name: truth-noise, noise_px: 2, seed: 1}   # or mediapipe; then track: triangulate
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
