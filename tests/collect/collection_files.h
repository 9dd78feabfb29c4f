// The files of a collection folder, compared byte for byte with the documented timing fields
// left out: what "sharding does not change the bytes" means in the tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/atomic_file.h"

namespace simcap::testing {

namespace fs = std::filesystem;

// Every file of a collection by relative path (OUT/slurm/ aside), timing fields left out
// (meta.json's timings, the render seconds of sequence.json and the index).
inline std::map<std::string, std::string> contents(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(root)) {
    const std::string rel = e.path().lexically_relative(root).string();
    if (!e.is_regular_file() || rel.rfind("slurm/", 0) == 0) continue;  // the array's own files
    std::string text = read_text(e.path());
    const std::string name = e.path().filename().string();
    if (name == "meta.json" || name == "sequence.json") {
      auto j = nlohmann::json::parse(text);
      j.erase("timings");
      j.erase("render_s");
      text = j.dump();
    } else if (name == "index.json") {
      auto j = nlohmann::json::parse(text);
      for (auto& s : j) s.erase("render_s");
      text = j.dump();
    } else if (name == "index.csv") {
      std::string stripped, line;
      std::istringstream in(text);
      while (std::getline(in, line)) {  // render_s is the sixth column
        size_t at = 0;
        for (int i = 0; i < 5; ++i) at = line.find(',', at) + 1;
        stripped += line.substr(0, at) + line.substr(line.find(',', at)) + "\n";
      }
      text = stripped;
    }
    files[rel] = text;
  }
  return files;
}

inline void expect_same(const fs::path& a, const fs::path& b) {
  const auto fa = contents(a), fb = contents(b);
  std::vector<std::string> na, nb;
  for (const auto& [k, v] : fa) na.push_back(k);
  for (const auto& [k, v] : fb) nb.push_back(k);
  ASSERT_EQ(na, nb);
  for (const auto& [k, v] : fa) EXPECT_TRUE(v == fb.at(k)) << k << " differs";
}

}  // namespace simcap::testing
