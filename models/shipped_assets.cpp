#include "models/shipped_assets.h"

namespace simcap {

std::filesystem::path asset_dir() {
  return std::filesystem::path(SIMCAP_ASSET_DIR);
}

std::filesystem::path resolve_asset_path(std::string_view text,
                                         const std::filesystem::path& base_dir) {
  if (text.starts_with(kAssetPrefix)) {
    return (asset_dir() / text.substr(kAssetPrefix.size())).lexically_normal();
  }
  return std::filesystem::absolute(base_dir / text).lexically_normal();
}

std::string asset_path_text(const std::filesystem::path& path) {
  const std::filesystem::path rel = path.lexically_relative(asset_dir().lexically_normal());
  if (!rel.empty() && rel != "." && *rel.begin() != "..") {
    return std::string(kAssetPrefix) + rel.generic_string();
  }
  return path.string();
}

}  // namespace simcap
