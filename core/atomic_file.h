// Writes a file under a temporary name and renames it into place on commit(), so a reader
// never sees a half-written output; an uncommitted file is removed when the object dies.
#pragma once

#include <filesystem>
#include <fstream>
#include <string_view>

namespace simcap {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Temporary path to write to; it keeps the target's extension so that format-by-extension
  // writers (OpenImageIO, cv::FileStorage) pick the right format.
  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& target() const { return target_; }
  // Renames the temporary file onto the target; throws Error when the rename fails.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

// Text content written atomically; creates parent folders.
void write_text_atomic(const std::filesystem::path& path, std::string_view text);
// Whole file as a string; throws Error naming the file when it cannot be read.
std::string read_text(const std::filesystem::path& path);

}  // namespace simcap
