#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <thread>

#include "tests/support/temp_dir.h"

namespace simcap::testing {

int run_shell(const std::string& command, std::string* output) {
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buf;
  std::string text;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) text.append(buf.data(), n);
  const int status = pclose(pipe);
  if (output) *output = text;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int run_simcap(const std::string& args, std::string* output) {
  return run_shell(std::string(SIMCAP_BINARY) + " " + args + " 2>&1", output);
}

int run_simcap_file_limited(const std::string& args, long max_file_bytes, std::string* output) {
  // sh's ulimit -f counts 512-byte blocks.
  return run_shell("ulimit -f " + std::to_string(max_file_bytes / 512) + "; trap '' XFSZ; exec " +
                       SIMCAP_BINARY + " " + args + " 2>&1",
                   output);
}

bool run_simcap_killed(const std::vector<std::string>& args, std::chrono::microseconds delay) {
  std::vector<std::string> words = {SIMCAP_BINARY};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return false;
  // Polled, so that a run that ends before the delay is reaped rather than killed.
  const auto end = std::chrono::steady_clock::now() + delay;
  int status = 0;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return WIFSIGNALED(status);
}

}  // namespace simcap::testing
