// A real one-node Slurm cluster (slurmctld, slurmd, munged) started on 127.0.0.1 in a temporary
// folder: `simcap collect --slurm --submit` runs stress/collections/small.yaml as a 4-task array
// whose output must be the single-process bytes. Skipped, saying so, where Slurm is not installed.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <random>
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

// The program's full path in the usual places, or empty.
fs::path program(const std::string& name) {
  for (const char* dir : {"/usr/sbin", "/usr/bin", "/usr/local/sbin", "/usr/local/bin"}) {
    if (fs::exists(fs::path(dir) / name)) return fs::path(dir) / name;
  }
  return {};
}

// A TCP port on 127.0.0.1 that is free now.
int free_port() {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof addr;
  bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
  close(fd);
  return ntohs(addr.sin_port);
}

// Output and status of a shell command.
int shell(const std::string& command, std::string* output = nullptr) {
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  std::string text;
  char buf[512];
  while (pipe && std::fgets(buf, sizeof buf, pipe)) text += buf;
  const int status = pipe ? pclose(pipe) : -1;
  if (output) *output = text;
  return status;
}

std::string file_text(const fs::path& p) {
  return fs::exists(p) ? read_text(p) : "(no " + p.string() + ")";
}

// The daemons this test started, stopped by their pid files when it ends.
class Cluster {
 public:
  explicit Cluster(fs::path dir) : dir_(std::move(dir)) {}
  ~Cluster() {
    for (const char* pid_file : {"slurmd.pid", "slurmctld.pid", "munge/munged.pid"}) {
      if (!fs::exists(dir_ / pid_file)) continue;
      const pid_t pid = std::stoi(read_text(dir_ / pid_file));
      kill(pid, SIGTERM);
      for (int i = 0; i < 100 && kill(pid, 0) == 0; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    }
  }
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
    ASSERT_EQ(shell(program("squeue").string() + " -h -j " + job, &queue), 0) << queue;
  }
  ASSERT_TRUE(queue.empty()) << "job " << job << " still queued after 120 s:\n" << queue;
}

TEST(SlurmCluster, FourTaskArrayGivesTheSingleProcessBytes) {
  for (const char* p : {"munged", "slurmctld", "slurmd", "sbatch", "squeue", "sinfo"}) {
    if (program(p).empty()) {
      GTEST_SKIP() << p << " is not installed: scripts/setup.sh installs slurmctld, slurmd, "
                   << "slurm-client and munge for this test";
    }
  }
  TempDir dir;
  const fs::path d = dir.path();
  fs::create_directories(d / "munge");
  fs::create_directories(d / "state");
  fs::create_directories(d / "spool");
  fs::permissions(d / "munge", fs::perms::owner_all, fs::perm_options::replace);
  {
    std::random_device random;  // a key, not an output: it may differ between runs
    std::ofstream key(d / "munge" / "munge.key", std::ios::binary);
    for (int i = 0; i < 1024; ++i) key.put(static_cast<char>(random()));
  }
  fs::permissions(d / "munge" / "munge.key", fs::perms::owner_read, fs::perm_options::replace);
  Cluster cluster(d);
  const std::string m = (d / "munge").string();
  std::string log;
  ASSERT_EQ(shell(program("munged").string() + " --force --key-file=" + m + "/munge.key --socket=" +
                      m + "/munge.socket --pid-file=" + m + "/munged.pid --log-file=" + m +
                      "/munged.log --seed-file=" + m + "/munged.seed",
                  &log),
            0)
      << "munged did not start: " << log << file_text(d / "munge" / "munged.log");

  char host[256] = {};
  gethostname(host, sizeof host - 1);
  const passwd* user = getpwuid(getuid());
  ASSERT_NE(user, nullptr);
  const fs::path conf = d / "slurm.conf";
  std::ofstream(conf) << "ClusterName=simcap\n"
                      << "SlurmctldHost=" << host << "(127.0.0.1)\n"
                      << "SlurmctldPort=" << free_port() << "\nSlurmdPort=" << free_port() << "\n"
                      << "SlurmUser=" << user->pw_name << "\nSlurmdUser=" << user->pw_name << "\n"
                      << "AuthType=auth/munge\nCryptoType=crypto/munge\n"
                      << "AuthInfo=socket=" << m << "/munge.socket\n"
                      << "StateSaveLocation=" << (d / "state").string() << "\n"
                      << "SlurmdSpoolDir=" << (d / "spool").string() << "\n"
                      << "SlurmctldPidFile=" << (d / "slurmctld.pid").string() << "\n"
                      << "SlurmdPidFile=" << (d / "slurmd.pid").string() << "\n"
                      << "SlurmctldLogFile=" << (d / "slurmctld.log").string() << "\n"
                      << "SlurmdLogFile=" << (d / "slurmd.log").string() << "\n"
                      << "ProctrackType=proctrack/linuxproc\nTaskPlugin=task/none\n"
                      << "MpiDefault=none\nSchedulerType=sched/builtin\n"
                      << "SelectType=select/cons_tres\nSelectTypeParameters=CR_CPU\n"
                      << "ReturnToService=2\nJobCompType=jobcomp/none\n"
                      << "AccountingStorageType=accounting_storage/none\n"
                      << "JobAcctGatherType=jobacct_gather/none\n"
                      << "NodeName=" << host << " NodeAddr=127.0.0.1 CPUs=2 RealMemory=4096\n"
                      << "PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP\n";
  setenv("SLURM_CONF", conf.c_str(), 1);
  ASSERT_EQ(shell(program("slurmctld").string() + " -f " + conf.string(), &log), 0)
      << "slurmctld did not start: " << log << file_text(d / "slurmctld.log");
  ASSERT_EQ(shell(program("slurmd").string() + " -f " + conf.string(), &log), 0)
      << "slurmd did not start: " << log << file_text(d / "slurmd.log");
  std::string state;
  for (int i = 0; i < 300 && state.rfind("idle", 0) != 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    shell(program("sinfo").string() + " -h -o %T", &state);
  }
  ASSERT_EQ(state.rfind("idle", 0), 0u)
      << "the node did not come up within 30 s: " << state << file_text(d / "slurmctld.log")
      << file_text(d / "slurmd.log");

  const std::string spec = std::string(SIMCAP_SOURCE_DIR) + "/stress/collections/small.yaml";
  std::string out;
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
      << out << file_text(d / "slurmd.log");
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
  ASSERT_EQ(shell(program("sbatch").string() + " --parsable " + script.string(), &out), 0) << out;
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
}

}  // namespace
}  // namespace simcap
