#include "core/stale_temporaries.h"

#include <string>

namespace simcap {
namespace fs = std::filesystem;

void remove_stale_temporaries(const fs::path& folder) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return;
  for (auto it = fs::recursive_directory_iterator(folder, ec);
       !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->is_regular_file() && name.size() > 1 && name[0] == '.' &&
        name.find(".tmp") != std::string::npos) {
      fs::remove(it->path(), ec);
    }
  }
}

}  // namespace simcap
