#include "core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <sstream>

#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;

AtomicFile::AtomicFile(fs::path target) : target_(std::move(target)) {
  static std::atomic<unsigned> counter{0};
  if (target_.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(target_.parent_path(), ec);
    if (ec) throw Error(target_.parent_path().string() + ": cannot create folder: " + ec.message());
  }
  temp_ = target_;
  std::string name(".");
  name += target_.stem().string();
  name += ".tmp" + std::to_string(getpid()) + "_" + std::to_string(counter++);
  name += target_.extension().string();
  temp_.replace_filename(name);
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    std::error_code ec;
    fs::remove(temp_, ec);
  }
}

void AtomicFile::commit() {
  std::error_code ec;
  fs::rename(temp_, target_, ec);
  if (ec)
    throw Error(target_.string() + ": cannot move the finished file into place: " + ec.message());
  committed_ = true;
}

void write_text_atomic(const fs::path& path, std::string_view text) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temp_path(), std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.flush();
    if (!out) throw Error(path.string() + ": write failed: " + std::strerror(errno));
  }
  file.commit();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open for reading: " + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace simcap
