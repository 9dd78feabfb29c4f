// `simcap bench collect`: a collection rendered by one process and by N shard processes at once
// on this machine, in the same run, and the cost of a process that finds nothing left to do.
#pragma once

#include <cstdio>
#include <filesystem>

namespace simcap {

struct CollectBenchOptions {
  std::filesystem::path simcap;  // the program the processes run (simcap itself)
  int shards = 2;
  int repeat = 3;  // runs; single and sharded alternate which goes first
};

// Prints the report; its last line is "single_frames_per_s=X sharded_frames_per_s=Y ratio=Y/X
// empty_task_s=Z" (medians over the runs). Each run collects into a new temporary folder.
void run_collect_benchmark(const std::filesystem::path& spec, const CollectBenchOptions& options,
                           std::FILE* out);

}  // namespace simcap
