// A dataset `simcap render` writes once for a whole test suite (from a fixture's
// SetUpTestSuite) into a temporary folder that goes with it, beside the suite's other files.
#pragma once

#include <filesystem>
#include <string>

#include "tests/support/temp_dir.h"

namespace simcap::testing {

class RenderedDataset {
 public:
  // `simcap render SCENE -o <path> -q ARGUMENTS`; ok() says whether it succeeded, log() why not.
  RenderedDataset(const std::string& scene, const std::string& arguments) {
    ok_ = run_simcap("render " + scene + " -o " + path().string() + " -q " + arguments, &log_) == 0;
  }
  bool ok() const { return ok_; }
  const std::string& log() const { return log_; }
  std::filesystem::path path() const { return dir_.path() / "d"; }
  // A path for another file of the suite, in the same temporary folder.
  std::filesystem::path file(const std::string& name) const { return dir_.path() / name; }

 private:
  TempDir dir_;
  bool ok_ = false;
  std::string log_;
};

}  // namespace simcap::testing
