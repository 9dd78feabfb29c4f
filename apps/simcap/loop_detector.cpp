#include "apps/simcap/loop_detector.h"

#include <spawn.h>
#include <sys/wait.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "models/detections.h"
#include "validate/keypoint_truth.h"

extern char** environ;

namespace simcap::cli {
namespace fs = std::filesystem;

namespace {

// The script of the source tree simcap was built from: it needs that tree's tools/mediapipe.
const fs::path kDetectMediapipe = SIMCAP_DETECT_MEDIAPIPE;

void run_mediapipe(const fs::path& dataset, const fs::path& file, bool quiet) {
  if (!fs::exists(kDetectMediapipe)) {
    throw Error("--detector mediapipe: " + kDetectMediapipe.string() +
                " not found (simcap runs it from the source tree it was built from)");
  }
  std::vector<std::string> words = {kDetectMediapipe.string(), dataset.string(), "-o",
                                    file.string()};
  if (quiet) words.push_back("--quiet");
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0) {
    throw Error("--detector mediapipe: cannot run " + kDetectMediapipe.string());
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw Error("--detector mediapipe: " + kDetectMediapipe.string() + " failed (" +
                (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                                   : std::string("killed")) +
                "; its message is above)");
  }
}

}  // namespace

void run_loop_detector(LoopDetector detector, const fs::path& dataset, const fs::path& file,
                       const TruthNoise& noise, bool quiet) {
  switch (detector) {
    case LoopDetector::none:
      return;
    case LoopDetector::mediapipe:
      run_mediapipe(dataset, file, quiet);
      return;
    case LoopDetector::truth_noise:
      write_coco_results(
          detections_from_truth(read_keypoint_truth(dataset, KeypointLayoutId::coco17), noise),
          file);
      return;
  }
}

}  // namespace simcap::cli
