// Comma-separated tables with a header line: a reader that checks the columns and reports bad
// cells as file:line: column, and a writer that publishes the file atomically when committed.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "core/atomic_file.h"

namespace simcap {

class CsvReader {
 public:
  // Opens `path` and checks that its header is exactly `columns`.
  CsvReader(std::filesystem::path path, std::vector<std::string> columns);
  // Advances to the next non-empty row; false at the end of the file.
  bool next();
  int line() const { return line_; }
  const std::string& text(int column) const;
  double number(int column) const;
  long integer(int column) const;
  [[noreturn]] void fail(int column, const std::string& message) const;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  std::vector<std::string> columns_;
  std::ifstream in_;
  std::vector<std::string> cells_;
  int line_ = 0;
};

class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& columns);
  std::ostream& out() { return out_; }
  // Flushes, checks the stream and renames the file into place.
  void commit();

 private:
  AtomicFile file_;
  std::ofstream out_;
};

// Splits one CSV line on commas (simcap's tables hold no quoted fields); strips a trailing CR.
std::vector<std::string> split_csv_line(std::string line);

}  // namespace simcap
