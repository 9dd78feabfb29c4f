#include "bench/collect_bench.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "collect/collection_spec.h"
#include "core/error.h"

extern char** environ;

namespace simcap {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

// Starts `args` with stdout and stderr on /dev/null.
pid_t start(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (err != 0) throw Error("bench collect: cannot start " + args[0]);
  return pid;
}

// Wall seconds of running the commands at once, each to completion; Error if one fails.
double run_all(const std::vector<std::vector<std::string>>& commands) {
  const auto t0 = Clock::now();
  std::vector<pid_t> pids;
  for (const auto& c : commands) pids.push_back(start(c));
  bool failed = false;
  for (const pid_t pid : pids) {
    int status = 0;
    waitpid(pid, &status, 0);
    failed |= !WIFEXITED(status) || WEXITSTATUS(status) != 0;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (failed) throw Error("bench collect: a simcap collect process failed");
  return seconds;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

void run_collect_benchmark(const fs::path& spec_file, const CollectBenchOptions& options,
                           std::FILE* out) {
  const CollectionSpec spec = load_collection(spec_file);
  const double frames = static_cast<double>(spec.count) * spec.frames;
  const fs::path work =
      fs::temp_directory_path() / ("simcap-bench-collect-" + std::to_string(getpid()));
  const std::string program = options.simcap.string(), file = spec.file.string();
  auto collect = [&](const fs::path& to, const std::string& shard) {
    return std::vector<std::string>{program,     "collect", file,      "-o",
                                    to.string(), "-q",      "--shard", shard};
  };
  std::vector<double> single_fps, sharded_fps, ratios, empty_s;
  for (int r = 0; r < options.repeat; ++r) {
    fs::remove_all(work);
    fs::create_directories(work);
    std::vector<std::vector<std::string>> shards;
    for (int k = 0; k < options.shards; ++k) {
      shards.push_back(
          collect(work / "sharded", std::to_string(k) + "/" + std::to_string(options.shards)));
    }
    double single = 0, sharded = 0;
    if (r % 2 == 0) {
      single = run_all({collect(work / "single", "0/1")});
      sharded = run_all(shards);
    } else {
      sharded = run_all(shards);
      single = run_all({collect(work / "single", "0/1")});
    }
    // A task whose sequences are all done: start-up, spec checks, index; no rendering.
    empty_s.push_back(run_all({collect(work / "single", "0/1")}));
    single_fps.push_back(frames / single);
    sharded_fps.push_back(frames / sharded);
    ratios.push_back(single / sharded);
    std::fprintf(out, "run %d: single %.2f s, %d shards %.2f s, ratio %.3f, empty task %.2f s\n",
                 r + 1, single, options.shards, sharded, single / sharded, empty_s.back());
  }
  fs::remove_all(work);
  std::fprintf(out, "%s: %d sequences x %d frames, %d shard processes, median of %d runs\n",
               file.c_str(), spec.count, spec.frames, options.shards, options.repeat);
  std::fprintf(out,
               "single_frames_per_s=%.3f sharded_frames_per_s=%.3f ratio=%.3f empty_task_s=%.3f\n",
               median(single_fps), median(sharded_fps), median(ratios), median(empty_s));
}

}  // namespace simcap
