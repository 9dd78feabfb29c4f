#include <sys/wait.h>

#include <array>
#include <cstdio>

#include "tests/support/temp_dir.h"

namespace simcap::testing {

int run_simcap(const std::string& args, std::string* output) {
  const std::string command = std::string(SIMCAP_BINARY) + " " + args + " 2>&1";
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

}  // namespace simcap::testing
