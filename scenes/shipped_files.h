// Files a scene refers to (motions, textures, meshes): relative to the scene file's folder, or
// to simcap's shipped assets with the prefix "asset:" (asset:cmu_131_01_start_walk_stop.bvh).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace simcap {

inline constexpr std::string_view kAssetPrefix = "asset:";

// models/assets of the source tree simcap was built from.
std::filesystem::path asset_dir();

// Absolute, lexically normal path of `text` as written in a scene file in `scene_dir`.
std::filesystem::path resolve_scene_file(std::string_view text,
                                         const std::filesystem::path& scene_dir);

// How a resolved path is written back: "asset:<name>" for a shipped asset (so the file stays
// valid in another checkout), the absolute path otherwise.
std::string scene_file_text(const std::filesystem::path& path);

}  // namespace simcap
