// simcap collect SPEC -o OUT: many sequences from one spec, sharded (--shard K/N), as a Slurm
// array (--slurm, --submit), and what is done, failed or missing (--status).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "apps/simcap/commands.h"
#include "collect/collection_job.h"
#include "collect/slurm_script.h"
#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap::cli {
namespace fs = std::filesystem;
namespace {

struct CollectArgs {
  fs::path spec, out, status;
  std::string shard = "0/1", ids;
  bool slurm = false, submit = false, quiet = false;
  int shards = 4, max_running = 0, cpus_per_task = 2;
};

std::pair<int, int> parse_shard(const std::string& text) {
  int k = 0, n = 0;
  char slash = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &k, &slash, &n, &extra) != 3 || slash != '/' || n < 1 ||
      k < 0 || k >= n) {
    throw Error("--shard: expected K/N with 0 <= K < N (e.g. 0/4), got '" + text + "'");
  }
  return {k, n};
}

fs::path slurm_script_path(const fs::path& out) {
  return out / "slurm" / "collect.sbatch";
}

// sbatch's job id (--parsable prints "id" or "id;cluster").
std::string submit(const fs::path& script) {
  const std::string command = "sbatch --parsable '" + script.string() + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) throw Error("--submit: cannot run sbatch");
  std::string text;
  char buf[512];
  while (std::fgets(buf, sizeof buf, pipe)) text += buf;
  const int status = pclose(pipe);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  if (status != 0) {
    throw Error("--submit: sbatch " + script.string() + " failed (is Slurm installed and " +
                "running?): " + text);
  }
  return text.substr(0, text.find(';'));
}

int run_slurm(const CollectArgs& a, const CollectionSpec& spec) {
  if (a.shards < 1) throw Error("--shards: expected at least 1");
  SlurmPlan plan;
  plan.simcap = fs::read_symlink("/proc/self/exe");
  plan.spec = spec.file;
  plan.out = fs::absolute(a.out).lexically_normal();
  plan.count = spec.count;
  plan.frames = spec.frames;
  plan.shards = static_cast<int>(
      std::min(static_cast<long long>(a.shards), static_cast<long long>(spec.count) * spec.frames));
  plan.max_running = a.max_running;
  plan.cpus_per_task = a.cpus_per_task;
  // The output is claimed before the measurement so that another spec's OUT is refused first.
  claim_collection_output(spec, plan.out);
  plan.cost = measure_frame_cost(spec, plan.out);
  fs::create_directories(plan.out / "slurm" / "logs");
  const fs::path script = slurm_script_path(plan.out);
  write_text_atomic(script, slurm_script(plan));
  fs::permissions(script, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  const nlohmann::ordered_json record = {{"shards", plan.shards},
                                         {"max_running", plan.max_running},
                                         {"cpus_per_task", plan.cpus_per_task},
                                         {"time_s", slurm_task_seconds(plan)},
                                         {"mem_mib", slurm_task_mib(plan)},
                                         {"measured_s_per_frame", plan.cost.seconds_per_frame},
                                         {"measured_threads", plan.cost.threads},
                                         {"measured_peak_mib", plan.cost.peak_mib}};
  write_text_atomic(plan.out / "slurm" / "plan.json", record.dump(2) + "\n");
  std::printf("simcap collect: %s (%d array tasks, %d CPUs, %ld s, %ld MiB each)\n",
              script.string().c_str(), plan.shards, plan.cpus_per_task, slurm_task_seconds(plan),
              slurm_task_mib(plan));
  if (a.submit) {
    std::printf("submitted job %s\n", submit(script).c_str());
  } else {
    std::printf("submit with: sbatch %s\n", script.string().c_str());
  }
  return 0;
}

int run_status(const fs::path& out) {
  const CollectionStatus s = collection_status(out);
  std::printf("simcap collect: %s (%s)\n", out.string().c_str(), s.spec.string().c_str());
  std::printf("  done     %d / %d\n  failed   %zu%s%s\n  missing  %zu%s%s\n",
              static_cast<int>(s.done.size()), s.count, s.failed.size(),
              s.failed.empty() ? "" : "  ", id_ranges(s.failed).c_str(), s.missing.size(),
              s.missing.empty() ? "" : "  ", id_ranges(s.missing).c_str());
  std::printf("index: %s\n", (out / "index.csv").string().c_str());
  std::vector<int> todo = s.failed;
  todo.insert(todo.end(), s.missing.begin(), s.missing.end());
  std::sort(todo.begin(), todo.end());
  if (todo.empty()) return 0;
  std::printf("re-run the %zu unfinished sequences:\n  simcap collect %s -o %s --ids %s\n",
              todo.size(), s.spec.string().c_str(), out.string().c_str(), id_ranges(todo).c_str());
  const fs::path plan = out / "slurm" / "plan.json";
  if (fs::exists(plan)) {
    const int shards = nlohmann::json::parse(read_text(plan)).at("shards").get<int>();
    std::printf("or on Slurm, the array tasks that hold them:\n  sbatch --array=%s %s\n",
                id_ranges(shards_holding(todo, s.count, s.frames, shards)).c_str(),
                slurm_script_path(out).string().c_str());
  }
  return 1;
}

int run_collect(const CollectArgs& a) {
  if (!a.status.empty()) return run_status(a.status);
  if (a.spec.empty() || a.out.empty()) {
    throw Error("collect: expected SPEC.yaml -o OUT, or --status OUT");
  }
  const CollectionSpec spec = load_collection(a.spec);
  if (a.slurm) return run_slurm(a, spec);
  const auto [shard, shards] = parse_shard(a.shard);
  CollectOptions options{.shard = shard, .shards = shards, .ids = {}, .quiet = a.quiet};
  if (!a.ids.empty()) options.ids = parse_id_ranges(a.ids, "--ids");
  const CollectSummary s = run_collection(spec, a.out, options);
  std::printf(
      "simcap collect: shard %d/%d: %d %s: %d rendered, %d done before, %d failed; "
      "%ld frames in %.1f s (%.2f frames/s) -> %s\n",
      shard, shards, s.selected, s.chunks > 1 ? "frame ranges" : "sequences", s.rendered, s.skipped,
      s.failed, s.frames, s.seconds,
      s.seconds > 0 ? static_cast<double>(s.frames) / s.seconds : 0.0, a.out.string().c_str());
  return s.failed > 0 ? 1 : 0;
}

}  // namespace

void add_collect(CLI::App& app, Action& action) {
  auto a = std::make_shared<CollectArgs>();
  auto* cmd = app.add_subcommand(
      "collect", "Render many sequences from one collection spec, sharded, locally or on Slurm");
  cmd->add_option("spec", a->spec, "Collection spec (YAML; see README.md, Collections)")
      ->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", a->out,
                  "Collection folder: seq_NNNNNN/ datasets, index.csv, index.json");
  cmd->add_option("--shard", a->shard,
                  "Render only shard K of N (sequences i with i % N == K; with fewer sequences "
                  "than shards, frame ranges of them), e.g. 2/4")
      ->default_str("0/1");
  cmd->add_option("--ids", a->ids, "Render only these sequences, e.g. 0-3,7 (see --status)");
  cmd->add_flag("--slurm", a->slurm,
                "Write OUT/slurm/collect.sbatch (an array of --shards tasks) instead of rendering");
  cmd->add_option("--shards", a->shards, "--slurm: array tasks (shards)")
      ->default_val(4)
      ->check(CLI::Range(1, 1000000));
  cmd->add_option("--max-running", a->max_running, "--slurm: tasks running at once (0: no limit)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--cpus-per-task", a->cpus_per_task, "--slurm: CPUs of each task")
      ->default_val(2)
      ->check(CLI::Range(1, 4096));
  cmd->add_flag("--submit", a->submit, "--slurm: submit the script with sbatch, print the job id");
  cmd->add_option("--status", a->status,
                  "Summarise OUT: done, failed and missing sequences, and how to re-run them")
      ->check(CLI::ExistingDirectory);
  cmd->add_flag("-q,--quiet", a->quiet, "No progress on stderr");
  cmd->footer(
      "Each sequence is a simcap dataset rendered into OUT/.staging/ and renamed into place when\n"
      "complete; a re-run skips finished sequences and continues an interrupted one. Shards are\n"
      "independent processes writing into the same OUT; sequence bytes do not depend on the\n"
      "sharding. With fewer sequences than shards each sequence is split into frame ranges,\n"
      "assembled into the sequence by the process that completes the last one.\n"
      "Exit status 1 when a sequence failed (--status: when some are unfinished).\n"
      "Examples:\n"
      "  simcap collect stress/collections/small.yaml -o out/c\n"
      "  simcap collect stress/collections/small.yaml -o out/c --shard 1/4\n"
      "  simcap collect stress/collections/long.yaml -o out/long --shard 0/2   (frame ranges)\n"
      "  simcap collect stress/collections/small.yaml -o out/c --slurm --shards 4 --submit\n"
      "  simcap collect --status out/c");
  cmd->callback([&action, a] { action = [a] { return run_collect(*a); }; });
}

}  // namespace simcap::cli
