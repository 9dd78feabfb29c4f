#include "scenes/shipped_files.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"
#include "scenes/scene.h"

namespace simcap {

std::filesystem::path asset_dir() {
  return std::filesystem::path(SIMCAP_ASSET_DIR);
}

std::filesystem::path resolve_scene_file(std::string_view text,
                                         const std::filesystem::path& scene_dir) {
  if (text.starts_with(kAssetPrefix)) {
    return (asset_dir() / text.substr(kAssetPrefix.size())).lexically_normal();
  }
  return std::filesystem::absolute(scene_dir / text).lexically_normal();
}

std::string scene_file_text(const std::filesystem::path& path) {
  const std::filesystem::path rel = path.lexically_relative(asset_dir().lexically_normal());
  if (!rel.empty() && rel != "." && *rel.begin() != "..") {
    return std::string(kAssetPrefix) + rel.generic_string();
  }
  return path.string();
}

std::filesystem::path shipped_scene_path(std::string_view name) {
  const std::filesystem::path dir(SIMCAP_SCENE_DIR);
  const std::filesystem::path path = dir / (std::string(name) + ".yaml");
  if (std::filesystem::is_regular_file(path)) return path;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  std::string list;
  for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
  throw Error("no shipped scene '" + std::string(name) + "' (shipped: " + list + ")");
}

}  // namespace simcap
