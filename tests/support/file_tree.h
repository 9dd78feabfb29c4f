// A folder's files as a map from relative path to content, for comparing outputs byte for byte.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "core/atomic_file.h"

namespace simcap::testing {

inline std::map<std::string, std::string> read_tree(const std::filesystem::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
    if (e.is_regular_file()) {
      files[std::filesystem::relative(e.path(), root).string()] = read_text(e.path());
    }
  }
  return files;
}

}  // namespace simcap::testing
