#include "core/stale_temporaries.h"

#include <string>

namespace simcap {
namespace fs = std::filesystem;

bool is_temporary_file_name(const fs::path& path) {
  const std::string name = path.filename().string();
  return name.size() > 1 && name[0] == '.' && name.find(".tmp") != std::string::npos;
}

void remove_stale_temporaries(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return;
  for (auto it = fs::recursive_directory_iterator(folder, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_regular_file() && is_temporary_file_name(it->path())) {
      fs::remove(it->path(), ec);
    }
  }
}

}  // namespace simcap
