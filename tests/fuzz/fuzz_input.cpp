#include "tests/fuzz/fuzz_input.h"

#include <algorithm>
#include <fstream>

#include "tests/support/temp_dir.h"

namespace simcap::fuzz {

namespace fs = std::filesystem;

const fs::path& fresh_scratch_dir() {
  static const testing::TempDir dir;
  for (const auto& entry : fs::directory_iterator(dir.path())) fs::remove_all(entry.path());
  return dir.path();
}

namespace {

void write_file(const fs::path& path, std::string_view bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

}  // namespace

fs::path write_input(std::string_view name, std::string_view bytes) {
  const fs::path path = fresh_scratch_dir() / name;
  write_file(path, bytes);
  return path;
}

fs::path write_parts(std::string_view input, std::initializer_list<std::string_view> names) {
  constexpr std::string_view open = "==> ", close = " <==";
  const fs::path& dir = fresh_scratch_dir();
  std::string_view name;
  std::size_t body = std::string_view::npos;
  auto flush = [&](std::size_t end) {
    if (body == std::string_view::npos) return;
    if (std::find(names.begin(), names.end(), name) != names.end()) {
      write_file(dir / name, input.substr(body, end - body));
    }
  };
  for (std::size_t pos = 0; pos < input.size();) {
    std::size_t eol = input.find('\n', pos);
    const std::size_t next = eol == std::string_view::npos ? input.size() : eol + 1;
    if (eol == std::string_view::npos) eol = input.size();
    const std::string_view line = input.substr(pos, eol - pos);
    if (line.size() > open.size() + close.size() && line.starts_with(open) &&
        line.ends_with(close)) {
      flush(pos);
      name = line.substr(open.size(), line.size() - open.size() - close.size());
      body = next;
    }
    pos = next;
  }
  flush(input.size());
  return dir;
}

}  // namespace simcap::fuzz
