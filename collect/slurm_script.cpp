#include "collect/slurm_script.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace simcap {
namespace {

// A path for a shell script line, in single quotes.
std::string shell_quoted(const std::filesystem::path& p) {
  std::string q = "'";
  for (char c : p.string()) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string slurm_time(long seconds) {
  const long minutes = (seconds + 59) / 60;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%ld-%02ld:%02ld:00", minutes / 1440, minutes / 60 % 24,
                minutes % 60);
  return buf;
}

}  // namespace

long slurm_task_seconds(const SlurmPlan& plan) {
  const int chunks = chunks_per_sequence(plan.count, plan.frames, plan.shards);
  const long long units = static_cast<long long>(plan.count) * chunks;
  const long long units_per_task = (units + plan.shards - 1) / plan.shards;
  const long long unit_frames = (plan.frames + chunks - 1) / chunks;
  const double thread_scale =
      static_cast<double>(plan.cost.threads) / std::max(1, plan.cpus_per_task);
  const double render_s = static_cast<double>(units_per_task * unit_frames) *
                          plan.cost.seconds_per_frame * thread_scale;
  return std::max(300L, static_cast<long>(std::ceil(3 * render_s)) + 120);
}

long slurm_task_mib(const SlurmPlan& plan) {
  const long mib = static_cast<long>(std::ceil(2 * plan.cost.peak_mib / 256)) * 256;
  return std::max(1024L, mib);
}

std::string slurm_script(const SlurmPlan& plan) {
  const auto logs = plan.out / "slurm" / "logs";
  std::string array = "0-" + std::to_string(plan.shards - 1);
  if (plan.max_running > 0) array += "%" + std::to_string(plan.max_running);
  char cost[160];
  std::snprintf(cost, sizeof cost, "# measured: %.3f s per frame on %d threads, peak %.0f MiB\n",
                plan.cost.seconds_per_frame, plan.cost.threads, plan.cost.peak_mib);
  std::string s = "#!/bin/bash\n";
  s += "# simcap collect: " + std::to_string(plan.count) + " sequences of " +
       std::to_string(plan.frames) + " frames in " + std::to_string(plan.shards) +
       " array tasks (written by simcap collect --slurm).\n";
  s += cost;
  s += "#SBATCH --job-name=simcap-collect\n";
  s += "#SBATCH --array=" + array + "\n";
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(plan.cpus_per_task) + "\n";
  s += "#SBATCH --time=" + slurm_time(slurm_task_seconds(plan)) + "\n";
  s += "#SBATCH --mem=" + std::to_string(slurm_task_mib(plan)) + "M\n";
  s += "#SBATCH --output=" + (logs / "%A_%a.out").string() + "\n";
  s += "#SBATCH --error=" + (logs / "%A_%a.err").string() + "\n";
  s += "set -euo pipefail\n";
  s += "exec " + shell_quoted(plan.simcap) + " collect " + shell_quoted(plan.spec) + " -o " +
       shell_quoted(plan.out) + " --shard \"${SLURM_ARRAY_TASK_ID}/" + std::to_string(plan.shards) +
       "\" --quiet\n";
  return s;
}

}  // namespace simcap
