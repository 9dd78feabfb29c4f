// The simcap program itself: help for every command, honest "not built yet", real versions.
#include <gtest/gtest.h>

#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::run_simcap;

TEST(Cli, HelpListsEveryCommand) {
  std::string out;
  EXPECT_EQ(run_simcap("--help", &out), 0);
  for (const char* cmd : {"render", "track", "validate", "loop", "demo", "stress", "bench", "model",
                          "motion", "ik-eval", "version"}) {
    EXPECT_NE(out.find(cmd), std::string::npos) << cmd;
    std::string sub;
    EXPECT_EQ(run_simcap(std::string(cmd) + " --help", &sub), 0) << cmd;
    EXPECT_NE(sub.find("Example"), std::string::npos) << cmd << ":\n" << sub;
  }
}

TEST(Cli, VersionShowsLibraryVersions) {
  std::string out;
  ASSERT_EQ(run_simcap("version", &out), 0);
  for (const char* lib : {"Embree       3.", "OpenImageIO  2.", "Assimp       5.",
                          "OpenCV       4.", "Eigen        3.", "urdfdom      "}) {
    EXPECT_NE(out.find(lib), std::string::npos) << lib << "\n" << out;
  }
}

TEST(Cli, UnknownCommandFails) {
  std::string out;
  EXPECT_NE(run_simcap("frobnicate", &out), 0);
  EXPECT_NE(run_simcap("", &out), 0);
}

}  // namespace
}  // namespace simcap
