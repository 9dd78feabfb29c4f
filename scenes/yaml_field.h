// A node of a parsed YAML file together with its key path (e.g. actors[0].motion.speed), so that
// every validation error names the file, the key path, the line and what was expected.
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace simcap::yaml {

// An override applied to the tree: its key path and the text the user gave ("rig.count=6").
struct AppliedOverride {
  std::string path;
  std::string text;
};

// Where a tree came from. Errors inside an overridden subtree name the override, not a line.
struct Origin {
  std::filesystem::path file;
  std::vector<AppliedOverride> overrides;
};

// An interval of allowed values, each end open or closed; any_finite() has both ends infinite.
struct Range {
  double lo;
  double hi;
  bool lo_closed = true;
  bool hi_closed = true;

  bool contains(double v) const;
  std::string describe() const;  // "in [0, 1]", "in (0, 1000]"; empty for any_finite()
};
Range closed(double lo, double hi);
Range positive(double hi);      // (0, hi]
Range non_negative(double hi);  // [0, hi]
Range any_finite();

// Shortest decimal text that reads back as exactly `v` (std::to_chars).
std::string format_number(double v);
std::string format_number(float v);

class Field {
 public:
  Field(YAML::Node node, std::string path, const Origin* origin);

  // The value of `key` in this map; its errors point at the key's line, where a reader looks
  // (a block map or list as the value starts on the next line).
  Field child(std::string_view key, YAML::Node value, const YAML::Mark& key_mark) const;

  const std::string& path() const { return path_; }
  const YAML::Node& node() const { return node_; }
  bool is_null() const { return !node_.IsDefined() || node_.IsNull(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_map() const { return node_.IsMap(); }

  // Throws Error "file:line: path: expected <expected>, got <what is there>".
  [[noreturn]] void expected(std::string_view expected) const;
  // Throws Error "file:line: path: <message>".
  [[noreturn]] void fail(std::string_view message) const;

  double number(const Range& range) const;
  float number_f(const Range& range) const;  // parsed directly as float (no double rounding)
  // `limit`, when given, says what the upper bound is (e.g. "simcap's largest image side").
  int integer(int lo, int hi, std::string_view limit = {}) const;
  std::uint64_t unsigned64() const;
  bool boolean() const;
  std::string text() const;  // any non-empty scalar

  // Elements of a sequence of `min`..`max` items, each with its indexed path.
  std::vector<Field> items(std::size_t min, std::size_t max) const;
  Eigen::Vector3d vector3(const Range& range) const;
  // A row-major rows x cols matrix written as a list of rows.
  Eigen::MatrixXd matrix(int rows, int cols) const;

 private:
  std::string describe_value() const;
  YAML::Node node_;
  std::string path_;
  const Origin* origin_;
  YAML::Mark mark_;
};

// A map read key by key: finish() rejects every key nobody took as unknown, listing the keys
// that were asked for. A null node (an empty section) reads as an empty map.
class Map {
 public:
  explicit Map(const Field& field);

  const Field& field() const { return field_; }
  bool has(std::string_view key);
  std::optional<Field> take(std::string_view key);
  Field require(std::string_view key);
  void finish() const;

 private:
  struct Entry {
    std::string key;
    Field value;
    bool taken = false;
  };
  Entry* find(std::string_view key);
  Field field_;
  std::vector<Entry> entries_;
  std::vector<std::string> asked_;
};

}  // namespace simcap::yaml
