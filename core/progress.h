// Progress of long work on stderr: items done / total, rate and time left. On a terminal it
// redraws one line; otherwise it prints a line at most every few seconds. Silent when quiet.
#pragma once

#include <chrono>
#include <mutex>
#include <string>

namespace simcap {

class Progress {
 public:
  Progress(std::string label, long total, bool quiet, std::string unit = "frames");
  ~Progress();
  // Marks `n` more items done; thread-safe.
  void advance(long n = 1);
  // Prints the final line (done, elapsed, mean rate); called by the destructor if not before.
  void finish();
  double elapsed_s() const;

 private:
  void print(bool final_line);
  std::string label_, unit_;
  long total_, done_ = 0;
  bool quiet_, tty_, finished_ = false;
  std::chrono::steady_clock::time_point start_, last_print_;
  std::mutex mutex_;
};

}  // namespace simcap
