#include "core/progress.h"

#include <unistd.h>

#include <cstdio>

namespace simcap {
using Clock = std::chrono::steady_clock;

Progress::Progress(std::string label, long total, bool quiet, std::string unit)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      quiet_(quiet),
      tty_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      last_print_(start_) {}

Progress::~Progress() {
  finish();
}

double Progress::elapsed_s() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

void Progress::advance(long n) {
  std::lock_guard lock(mutex_);
  done_ += n;
  const auto now = Clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since >= (tty_ ? 0.2 : 5.0)) {
    last_print_ = now;
    print(false);
  }
}

void Progress::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  print(true);
}

void Progress::print(bool final_line) {
  if (quiet_) return;
  const double t = elapsed_s();
  const double rate = t > 0 ? done_ / t : 0.0;
  char line[256];
  if (final_line) {
    std::snprintf(line, sizeof line, "%s: %ld/%ld %s in %.1f s (%.1f %s/s)", label_.c_str(), done_,
                  total_, unit_.c_str(), t, rate, unit_.c_str());
  } else {
    const double left = rate > 0 ? (total_ - done_) / rate : 0.0;
    std::snprintf(line, sizeof line, "%s: %ld/%ld %s, %.1f %s/s, %.0f s left", label_.c_str(),
                  done_, total_, unit_.c_str(), rate, unit_.c_str(), left);
  }
  if (tty_) {
    std::fprintf(stderr, "\r\033[K%s%s", line, final_line ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s\n", line);
  }
  std::fflush(stderr);
}

}  // namespace simcap
