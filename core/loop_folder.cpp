#include "core/loop_folder.h"

#include <string>

#include "core/error.h"

namespace simcap {

namespace fs = std::filesystem;

void refuse_loop_folder(const fs::path& dir, std::string_view part) {
  const fs::path meant = dir / part;
  if (!fs::is_directory(meant) || fs::exists(dir / "meta.json") ||
      fs::exists(dir / "joints3d.csv")) {
    return;
  }
  throw Error(dir.string() + ": the output folder of simcap loop or demo, not a " +
              std::string(part) + "; its " + std::string(part) + " is " + meant.string());
}

}  // namespace simcap
