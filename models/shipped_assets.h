// simcap's shipped assets (models/assets/ of the source tree: motion clips, a body, the joint
// limits) and file paths that may name them as "asset:<name>" (scene files, dataset scenes).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace simcap {

inline constexpr std::string_view kAssetPrefix = "asset:";

// models/assets of the source tree simcap was built from.
std::filesystem::path asset_dir();

// Absolute, lexically normal path of `text` as written in a file in `base_dir`: "asset:<name>"
// is a shipped asset, a relative path starts at `base_dir`.
std::filesystem::path resolve_asset_path(std::string_view text,
                                         const std::filesystem::path& base_dir);

// How a resolved path is written back: "asset:<name>" for a shipped asset (so the file stays
// valid in another checkout), the absolute path otherwise.
std::string asset_path_text(const std::filesystem::path& path);

}  // namespace simcap
