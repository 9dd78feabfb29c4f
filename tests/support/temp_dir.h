// A fresh folder under the system temporary directory for one test, removed afterwards.
#pragma once

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace simcap::testing {

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("simcap_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// Runs `command` with sh; returns its exit status and captures its stdout into `output`.
int run_shell(const std::string& command, std::string* output = nullptr);
// Runs the simcap program with `args` (a shell-quoted string); returns its exit status and
// captures stdout+stderr into `output`.
int run_simcap(const std::string& args, std::string* output = nullptr);
// The same with no file allowed to grow beyond `max_file_bytes` (ulimit -f): writes beyond
// fail with EFBIG (SIGXFSZ is ignored), as they do on a full disk.
int run_simcap_file_limited(const std::string& args, long max_file_bytes,
                            std::string* output = nullptr);

// `args` as one shell-quoted string for run_simcap (no argument may hold a single quote).
inline std::string shell_words(const std::vector<std::string>& args) {
  std::string line;
  for (const auto& a : args) line += " '" + a + "'";
  return line;
}

// Runs the simcap program with `args` (one per argument, no shell; output discarded) and kills
// it with SIGKILL after `delay` unless it ended before. Returns true when it was killed.
bool run_simcap_killed(const std::vector<std::string>& args, std::chrono::microseconds delay);

}  // namespace simcap::testing
