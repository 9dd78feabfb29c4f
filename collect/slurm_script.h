// The sbatch array script of a collection: one array task per shard, with CPU, time and memory
// requests derived from a per-frame cost measured on this machine.
#pragma once

#include <filesystem>
#include <string>

#include "collect/collection_job.h"

namespace simcap {

struct SlurmPlan {
  std::filesystem::path simcap;  // the program the tasks run (absolute)
  std::filesystem::path spec, out;
  int count = 0;        // sequences
  int frames = 0;       // frames per sequence
  int shards = 1;       // array tasks
  int max_running = 0;  // tasks at once (%M); 0: no limit
  int cpus_per_task = 2;
  FrameCost cost;
};

// Wall time one task may take, in seconds: the frames of its units (shard_units) at the
// measured cost, scaled from this
// machine's threads to cpus_per_task, times 3 for slower nodes and a shared filesystem, plus
// 2 minutes of start-up; at least 5 minutes.
long slurm_task_seconds(const SlurmPlan& plan);
// Memory per task in MiB: twice the measured peak, rounded up to 256 MiB, at least 1024.
long slurm_task_mib(const SlurmPlan& plan);

// The script's text (bash with #SBATCH lines; logs in OUT/slurm/logs/%A_%a.{out,err}).
std::string slurm_script(const SlurmPlan& plan);

}  // namespace simcap
