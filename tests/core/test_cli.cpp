// The simcap program itself: help for every command, honest "not built yet", real versions.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using simcap::testing::run_simcap;

// Every command and subcommand, as typed after `simcap`.
constexpr const char* kEveryCommand[] = {
    "render",      "track",           "validate",       "loop",
    "demo",        "stress",          "bench",          "model",
    "motion",      "ik-eval",         "gestures",       "export",
    "detections",  "collect",         "version",        "bench render",
    "bench track", "bench ik",        "bench collect",  "model info",
    "model urdf",  "model mesh",      "model limits",   "model joint-names",
    "motion dump", "motion retarget", "motion generate"};

TEST(Cli, HelpListsEveryCommand) {
  std::string out;
  EXPECT_EQ(run_simcap("--help", &out), 0);
  for (const char* cmd : kEveryCommand) {
    if (std::string(cmd).find(' ') == std::string::npos) {
      EXPECT_NE(out.find(cmd), std::string::npos) << cmd;
    }
    // Every command's help, the second level's too, shows examples.
    std::string sub;
    EXPECT_EQ(run_simcap(std::string(cmd) + " --help", &sub), 0) << cmd;
    EXPECT_NE(sub.find("Example"), std::string::npos) << cmd << ":\n" << sub;
  }
}

// An example is run from the repository's root as printed: a shipped file it names (a scene, a
// sweep, a clip) carries its folder and exists, so copying the line works.
TEST(Cli, HelpExamplesNameShippedFilesByTheirPath) {
  const fs::path root = SIMCAP_SOURCE_DIR;
  std::set<std::string> shipped;
  for (const char* folder : {"scenes", "stress", "stress/collections", "models/assets"}) {
    for (const auto& entry : fs::directory_iterator(root / folder)) {
      shipped.insert(entry.path().filename().string());
    }
  }
  // Words of file-name characters ending in a shipped file's extension (std::regex trips gcc
  // 12's -Wmaybe-uninitialized in the sanitizer build).
  const auto file_names = [](const std::string& text) {
    std::vector<std::string> names;
    std::string word;
    for (char c : text + " ") {
      if (std::isalnum(static_cast<unsigned char>(c)) ||
          std::string_view("_./-").find(c) != std::string_view::npos) {
        word += c;
        continue;
      }
      while (!word.empty() && word.back() == '.') word.pop_back();
      for (const char* ext : {".yaml", ".bvh", ".x3d", ".urdf", ".amc", ".asf"}) {
        if (word.ends_with(ext)) names.push_back(word);
      }
      word.clear();
    }
    return names;
  };
  for (const char* cmd : kEveryCommand) {
    std::string help;
    ASSERT_EQ(run_simcap(std::string(cmd) + " --help", &help), 0) << cmd;
    for (const std::string& name : file_names(help)) {
      const fs::path named = name;
      if (named.has_parent_path()) {
        const std::string top = named.begin()->string();
        if (top == "scenes" || top == "stress" || top == "models") {
          EXPECT_TRUE(fs::exists(root / named)) << cmd << ": " << named;
        }
      } else {
        EXPECT_EQ(shipped.count(named.string()), 0u)
            << cmd << ": the shipped " << named << " without its folder";
      }
    }
  }
}

// A default shown in a help text is the one the command uses.
TEST(Cli, HelpShowsTheDefaultsInUse) {
  std::string help;
  ASSERT_EQ(run_simcap("validate --help", &help), 0);
  EXPECT_EQ(help.find("=coco17"), std::string::npos) << help;  // read from the detections
  EXPECT_NE(help.find("(default: from the keypoint count or names)"), std::string::npos) << help;
  ASSERT_EQ(run_simcap("demo --help", &help), 0);
  EXPECT_NE(help.find("--frames INT:> 0=240        Frames to render\n"), std::string::npos) << help;
  ASSERT_EQ(run_simcap("render --help", &help), 0);
  EXPECT_NE(help.find("gt/keypoints_coco.json"), std::string::npos) << help;
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
  EXPECT_EQ(run_simcap("frobnicate", &out), 1);
  EXPECT_EQ(run_simcap("", &out), 1);
}

// A bad option is bad input like any other: status 1, as the help texts state, not CLI11's own
// codes (105 for a bad value, 106 for a missing one), which scripts checking for 1 would miss.
TEST(Cli, BadOptionsExitWithStatusOne) {
  const std::string scene = std::string(SIMCAP_SOURCE_DIR) + "/scenes/studio4.yaml";
  for (const std::string& args : {"render " + scene + " -o never --frames 0", "render " + scene,
                                  std::string("track /nonexistent/dataset -o never"),
                                  std::string("validate --no-such-option")}) {
    std::string out;
    EXPECT_EQ(run_simcap(args, &out), 1) << args << ":\n" << out;
  }
}

// Bounded numbers name the option, what was expected and what was given, before any work.
TEST(Cli, OutOfRangeNumbersSayWhatWasExpected) {
  const std::string scene = std::string(SIMCAP_SOURCE_DIR) + "/scenes/studio4.yaml";
  const std::string bvh = std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_03_start_hop_stop.bvh";
  const std::pair<std::string, std::string> cases[] = {
      {"render " + scene + " -o never --frames 0",
       "--frames: expected a number greater than 0, got '0'"},
      {"render " + scene + " -o never --frames x",
       "--frames: expected a number greater than 0, got 'x'"},
      {"motion generate walk_path -o never.bvh --speed -1",
       "--speed: expected a number greater than 0"},
      // CLI11 alone reads a negative unsigned seed as 2^64 - 1.
      {"render " + scene + " -o never --seed -1",
       "--seed: expected a number of at least 0, got '-1'"},
      {"track " + std::string(SIMCAP_SOURCE_DIR) + " -o never --seed -2",
       "--seed: expected a number of at least 0, got '-2'"},
      {"ik-eval " + bvh + " --frames 0 -o never",  // as render's and track's: 0 is not "all"
       "--frames: expected a number greater than 0, got '0'"},
      {"ik-eval " + bvh + " --pelvis-weights 1,-1,0 -o never",
       "--pelvis-weights: expected a number of at least 0, got '-1'"}};
  for (const auto& [args, message] : cases) {
    std::string out;
    EXPECT_NE(run_simcap(args, &out), 0) << args;
    EXPECT_NE(out.find(message), std::string::npos) << args << ":\n" << out;
  }
}

// SIK's cue options are the same in ik-eval and track (one solver), and name bad values.
TEST(Cli, SikCueOptionsNameTheirBadValues) {
  const std::string bvh = std::string(SIMCAP_MOCAP_DIR) + "/cmu_131_03_start_hop_stop.bvh";
  for (const std::string& command :
       {"ik-eval " + bvh, "track " + std::string(SIMCAP_SOURCE_DIR) + " --method sik"}) {
    std::string out;
    EXPECT_NE(run_simcap(command + " --spine-bend curve -o never", &out), 0) << command;
    EXPECT_NE(out.find("--spine-bend: unknown value 'curve' (expected thesis or lean)"),
              std::string::npos)
        << command << ":\n"
        << out;
    EXPECT_NE(run_simcap(command + " --pelvis-travel -1 -o never", &out), 0) << command;
    EXPECT_NE(out.find("--pelvis-travel: expected a number of at least 0, got '-1'"),
              std::string::npos)
        << command << ":\n"
        << out;
  }
}

}  // namespace
}  // namespace simcap
