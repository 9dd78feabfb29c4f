// A real one-node Slurm cluster (slurmctld, slurmd, munged) started on 127.0.0.1 in a temporary
// folder by scripts/slurm_local.sh: `simcap collect --slurm --submit` runs
// stress/collections/small.yaml as a 4-task array whose output must be the single-process bytes.
// Skipped, saying so, where Slurm is not installed.
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "core/atomic_file.h"
#include "tests/collect/collection_files.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using testing::expect_same;
using testing::run_simcap;
using testing::TempDir;
namespace fs = std::filesystem;

// Output and exit status of a shell command.
int shell(const std::string& command, std::string* output = nullptr) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string text;
  char buf[512];
  while (pipe && std::fgets(buf, sizeof buf, pipe)) text += buf;
  const int status = pipe ? pclose(pipe) : -1;
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

const std::string kScript = std::string(SIMCAP_SOURCE_DIR) + "/scripts/slurm_local.sh";

// The cluster's daemons, stopped by the script (by their pid files) when the test ends.
class Cluster {
 public:
  explicit Cluster(fs::path dir) : dir_(std::move(dir)) {}
  ~Cluster() { shell(kScript + " stop " + dir_.string()); }
  Cluster(const Cluster&) = delete;
  Cluster& operator=(const Cluster&) = delete;

 private:
  fs::path dir_;
};

// Waits (at most 120 s) until `job` has left the queue.
void wait_for(const std::string& job) {
  std::string queue = "?";
  for (int i = 0; i < 1200 && !queue.empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_EQ(shell("squeue -h -j " + job, &queue), 0) << queue;
  }
  ASSERT_TRUE(queue.empty()) << "job " << job << " still queued after 120 s:\n" << queue;
}

TEST(SlurmCluster, FourTaskArrayGivesTheSingleProcessBytes) {
  TempDir dir;
  const fs::path d = dir.path();
  Cluster cluster(d);
  std::string out;
  const int started = shell(kScript + " start " + d.string(), &out);
  // Exit status 3: a package is missing; the script's message names it.
  if (started == 3) GTEST_SKIP() << out;
  ASSERT_EQ(started, 0) << out;
  const std::string conf = (d / "slurm.conf").string();
  ASSERT_NE(out.find("export SLURM_CONF=" + conf + "\n"), std::string::npos) << out;
  // What `eval "$(scripts/slurm_local.sh start DIR)"` does in a user's shell; simcap's sbatch
  // and the squeue calls below inherit it.
  setenv("SLURM_CONF", conf.c_str(), 1);
  ASSERT_NE(shell(kScript + " start " + d.string(), &out), 0) << "a second start must refuse";
  EXPECT_NE(out.find("a cluster already runs in " + d.string()), std::string::npos) << out;

  const std::string spec = std::string(SIMCAP_SOURCE_DIR) + "/stress/collections/small.yaml";
  ASSERT_EQ(run_simcap("collect " + spec + " -o " + (d / "array").string() +
                           " --slurm --shards 4 --cpus-per-task 1 --submit",
                       &out),
            0)
      << out;
  const size_t at = out.find("submitted job ");
  ASSERT_NE(at, std::string::npos) << out;
  const std::string job = out.substr(at + 14, out.find('\n', at) - at - 14);
  ASSERT_NO_FATAL_FAILURE(wait_for(job));
  ASSERT_EQ(run_simcap("collect --status " + (d / "array").string(), &out), 0)
      << out << read_text(d / "slurmd.log");
  EXPECT_EQ(std::distance(fs::directory_iterator(d / "array" / "slurm" / "logs"), {}), 8)
      << "one .out and one .err per array task";
  ASSERT_EQ(run_simcap("collect " + spec + " -o " + (d / "one").string() + " -q", &out), 0) << out;
  expect_same(d / "one", d / "array");

  // The overhead of a Slurm task, measured (printed, not asserted): the same array submitted
  // again, every task finding its sequences done. A task's log files are created when Slurm
  // starts it (.err stays empty) and .out is last written by simcap's final line, so their
  // times bound the task's whole life in the allocation: launch, simcap's start-up, spec
  // checks, index.
  const fs::path script = d / "array" / "slurm" / "collect.sbatch";
  const auto submitted = std::chrono::system_clock::now();
  ASSERT_EQ(shell("sbatch --parsable " + script.string(), &out), 0) << out;
  const std::string empty_job = out.substr(0, out.find_first_of(";\n"));
  ASSERT_NO_FATAL_FAILURE(wait_for(empty_job));
  const double array_s =
      std::chrono::duration<double>(std::chrono::system_clock::now() - submitted).count();
  std::vector<double> task_s;
  double first_start_s = 1e9;
  for (int k = 0; k < 4; ++k) {
    const fs::path log = d / "array" / "slurm" / "logs" / (empty_job + "_" + std::to_string(k));
    const auto start = std::chrono::file_clock::to_sys(fs::last_write_time(log.string() + ".err"));
    const auto end = std::chrono::file_clock::to_sys(fs::last_write_time(log.string() + ".out"));
    task_s.push_back(std::chrono::duration<double>(end - start).count());
    first_start_s =
        std::min(first_start_s, std::chrono::duration<double>(start - submitted).count());
  }
  std::sort(task_s.begin(), task_s.end());
  std::printf(
      "[measure] Slurm task overhead (4 tasks with nothing to do, 2 CPUs): per task %.2f s "
      "median, %.2f s max (first log to last output); submit to first task start %.2f s; "
      "submit to array done %.2f s\n",
      0.5 * (task_s[1] + task_s[2]), task_s[3], first_start_s, array_s);

  ASSERT_EQ(shell(kScript + " status " + d.string(), &out), 0) << out;
  EXPECT_NE(out.find("slurmd: running"), std::string::npos) << out;
  ASSERT_EQ(shell(kScript + " stop " + d.string(), &out), 0) << out;
  EXPECT_EQ(shell(kScript + " stop " + d.string(), &out), 0) << "stop twice: " << out;
  EXPECT_EQ(shell(kScript + " status " + d.string(), &out), 1) << out;
  EXPECT_NE(out.find("slurmctld: stopped"), std::string::npos) << out;
}

TEST(SlurmLocalScript, RefusesBadUsage) {
  std::string out;
  for (const std::string args : {"", " start", " start ''", " restart /tmp"}) {
    EXPECT_EQ(shell(kScript + args, &out), 2) << args;
    EXPECT_NE(out.find("usage: "), std::string::npos) << args << ": " << out;
  }
}

}  // namespace
}  // namespace simcap
