#include "core/csv.h"

#include <cerrno>
#include <charconv>
#include <cstring>

#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;

std::vector<std::string> split_csv_line(std::string line) {
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::vector<std::string> cells;
  size_t start = 0;
  while (true) {
    const size_t comma = line.find(',', start);
    cells.push_back(line.substr(start, comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

CsvReader::CsvReader(fs::path path, std::vector<std::string> columns)
    : path_(std::move(path)), columns_(std::move(columns)), in_(path_) {
  if (!in_) throw Error(path_.string() + ": cannot open: " + std::strerror(errno));
  std::string header;
  if (!std::getline(in_, header)) throw_input_error(path_, 1, "header", "the file is empty");
  line_ = 1;
  const auto got = split_csv_line(header);
  if (got != columns_) {
    std::string expected;
    for (const auto& c : columns_) expected += (expected.empty() ? "" : ",") + c;
    throw_input_error(path_, 1, "header", "expected columns '" + expected + "'");
  }
}

bool CsvReader::next() {
  std::string line;
  while (std::getline(in_, line)) {
    ++line_;
    if (line.empty() || line == "\r") continue;
    cells_ = split_csv_line(line);
    if (cells_.size() != columns_.size()) {
      throw_input_error(path_, line_, "",
                        "expected " + std::to_string(columns_.size()) + " columns, got " +
                            std::to_string(cells_.size()));
    }
    return true;
  }
  return false;
}

const std::string& CsvReader::text(int column) const {
  return cells_.at(column);
}

double CsvReader::number(int column) const {
  const std::string& s = text(column);
  double v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size())
    fail(column, "expected a number, got '" + s + "'");
  return v;
}

long CsvReader::integer(int column) const {
  const std::string& s = text(column);
  long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size())
    fail(column, "expected an integer, got '" + s + "'");
  return v;
}

void CsvReader::fail(int column, const std::string& message) const {
  throw_input_error(path_, line_, "column '" + columns_.at(column) + "'", message);
}

CsvWriter::CsvWriter(const fs::path& path, const std::vector<std::string>& columns)
    : file_(path), out_(file_.temp_path()) {
  if (!out_) throw Error(path.string() + ": cannot open for writing");
  for (size_t i = 0; i < columns.size(); ++i) out_ << (i ? "," : "") << columns[i];
  out_ << '\n';
}

void CsvWriter::commit() {
  out_.flush();
  if (!out_) throw Error(file_.target().string() + ": write failed: " + std::strerror(errno));
  out_.close();
  file_.commit();
}

}  // namespace simcap
