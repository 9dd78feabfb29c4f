#include "scenes/scene.h"

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.h"

namespace simcap {

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
