// The include rules of docs/ARCHITECTURE.md, checked on the sources: each library folder may
// include only its own headers and those of the libraries beneath it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace simcap {
namespace {

namespace fs = std::filesystem;

// Folder -> the simcap folders its files may include (besides its own).
const std::map<std::string, std::vector<std::string>>& allowed() {
  static const std::map<std::string, std::vector<std::string>> rules = {
      {"core", {}},
      {"models", {"core"}},
      {"scenes", {"core", "models"}},
      {"sim", {"core", "models", "scenes"}},
      {"collect", {"core", "models", "scenes", "sim"}},
      {"tracker/common", {"core"}},
      {"tracker/moschini", {"core", "models", "tracker/common"}},
      {"tracker/unzueta", {"core", "models", "tracker/common"}},
      {"tracker/gomez", {"core", "models", "tracker/common"}},
      {"tracker/triangulate", {"core", "models", "tracker/common"}},
      {"tracker",
       {"core", "models", "tracker/common", "tracker/moschini", "tracker/unzueta", "tracker/gomez",
        "tracker/triangulate"}},
      {"validate", {"core", "models"}},
      {"bench",
       {"core", "models", "scenes", "sim", "collect", "tracker", "tracker/common",
        "tracker/moschini", "tracker/unzueta", "tracker/gomez", "tracker/triangulate"}},
  };
  return rules;
}

// The simcap folder a quoted include names: its path up to the file, e.g. "tracker/common".
std::string folder_of(const std::string& include) {
  return fs::path(include).parent_path().string();
}

bool may_include(const std::string& folder, const std::string& target) {
  const std::vector<std::string>& below = allowed().at(folder);
  return target == folder || std::find(below.begin(), below.end(), target) != below.end();
}

TEST(Layering, EveryIncludeFollowsTheArrows) {
  const fs::path root = SIMCAP_SOURCE_DIR;
  int files = 0;
  for (const auto& [folder, rules] : allowed()) {
    if (!fs::is_directory(root / folder)) continue;
    for (const auto& entry : fs::directory_iterator(root / folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext != ".h" && ext != ".cpp") continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n) {
        if (line.rfind("#include \"", 0) != 0) continue;
        const std::string target = folder_of(line.substr(10, line.find('"', 10) - 10));
        EXPECT_TRUE(may_include(folder, target))
            << entry.path().lexically_relative(root).string() << ":" << n << ": " << line << " ("
            << folder << " may not include " << target << "/)";
      }
    }
  }
  EXPECT_GT(files, 100);  // the scan found the sources
}

}  // namespace
}  // namespace simcap
