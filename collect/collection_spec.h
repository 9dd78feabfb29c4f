// A collection spec (YAML): scenes x motions x bodies x colours x camera jitter x any scene key,
// a count and a master seed; expanded into the numbered sequences of a dataset collection.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace simcap {

// A value of the spec that may vary: one fixed value, a list of choices, or a uniform range
// [lo, hi] (integers when both ends are written as integers).
struct CollectionParam {
  std::string key;                   // scene key path ("actors[0].height") or motion key
  std::vector<std::string> choices;  // YAML texts; one entry: fixed
  bool is_range = false;
  double lo = 0, hi = 0;
  bool integer = false;
  int line = 0;
};

// One choice of motion: a file (a BVH or an AMC with its ASF) or a procedural kind whose
// parameters may be ranges.
struct CollectionMotion {
  std::string label;  // file name or procedural kind (the index's motion)
  std::vector<std::pair<std::string, std::string>> fixed;  // motion keys and YAML values
  std::vector<CollectionParam> params;  // procedural parameters that vary (speed, radius, ...)
  int line = 0;
};

struct CollectionSpec {
  std::filesystem::path file;
  std::string text;  // the file as read (a collection's OUT records it)
  int count = 0;
  std::uint64_t seed = 0;
  int frames = 0;
  std::vector<std::filesystem::path> scenes;
  std::vector<int> scene_lines;
  std::vector<std::string> set;  // fixed "key=value" scene overrides
  std::vector<CollectionMotion> motions;
  std::vector<CollectionParam> params;  // bodies, colours, vary and camera_jitter, in file order
  bool camera_jitter = false;           // rig.jitter's seed is each sequence's render seed
};

// One sequence of the collection, fully resolved.
struct CollectionSequence {
  int id = 0;
  std::filesystem::path scene;
  std::string motion;                                           // the motion's label
  std::uint64_t seed = 0;                                       // the render seed
  std::vector<std::pair<std::string, std::string>> parameters;  // key -> value, for the index
  std::vector<std::string> overrides;  // "key=value" for load_scene, `set` first
};

// Reads and checks a collection spec: unknown keys, empty lists, bad ranges, missing files,
// motion folders without clips and scene values the scenes refuse are Errors naming the spec's
// file:line and key.
//
//   count: 16
//   seed: 7
//   frames: 3
//   scenes: [../../scenes/studio4.yaml]
//   set: {rig.resolution: [64, 48]}
//   motions:
//     - folder: ../../models/assets
//     - {procedural: walk_path, speed: {uniform: [0.8, 1.6]}}
//   bodies: {height: {uniform: [1.55, 1.95]}, girth: [0.9, 1.1]}
//   colors: {shirt: ["#aa2222", "#2244aa"]}
//   vary: {rig.height: {uniform: [2.2, 2.6]}}
//   camera_jitter: {position_m: {uniform: [0, 0.05]}, rotation_deg: 2}
CollectionSpec load_collection(const std::filesystem::path& file);

// Sequence `id` (0 <= id < spec.count). Lists of scenes, motions and parameters are crossed in
// order (the last fastest, cycling when count is larger); ranges and the render seed are drawn
// from a generator seeded by the master seed and `id` alone, so a sequence does not depend on
// which others are rendered.
CollectionSequence collection_sequence(const CollectionSpec& spec, int id);

}  // namespace simcap
