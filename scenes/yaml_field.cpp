#include "scenes/yaml_field.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/literal_text.h"

namespace simcap::yaml {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Overridden subtrees have no line in the file; the override names them instead.
const AppliedOverride* override_covering(const Origin& origin, const std::string& path) {
  for (auto it = origin.overrides.rbegin(); it != origin.overrides.rend(); ++it) {
    const std::string& p = it->path;
    if (path.size() >= p.size() && path.compare(0, p.size(), p) == 0 &&
        (path.size() == p.size() || path[p.size()] == '.' || path[p.size()] == '[')) {
      return &*it;
    }
  }
  return nullptr;
}

std::string child_path(const std::string& parent, std::string_view key) {
  return parent.empty() ? std::string(key) : parent + "." + std::string(key);
}

// YAML allows a leading '+' on numbers; std::from_chars does not.
std::string_view strip_plus(std::string_view s) {
  return !s.empty() && s.front() == '+' ? s.substr(1) : s;
}

template <typename T>
bool parse_exact(std::string_view s, T& out) {
  s = strip_plus(s);
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && ptr == end;
}

template <typename T>
T parse_number(const Field& f, const Range& range) {
  const std::string what = range.describe().empty() ? "a number" : "a number " + range.describe();
  T v = 0;
  if (!f.is_scalar() || !parse_exact(f.node().Scalar(), v) || !std::isfinite(v) ||
      !range.contains(v)) {
    f.expected(what);
  }
  return v;
}

}  // namespace

bool Range::contains(double v) const {
  return (lo_closed ? v >= lo : v > lo) && (hi_closed ? v <= hi : v < hi);
}

std::string Range::describe() const {
  if (lo == -kInf && hi == kInf) return "";
  return std::string("in ") + (lo_closed ? "[" : "(") + format_number(lo) + ", " +
         format_number(hi) + (hi_closed ? "]" : ")");
}

Range closed(double lo, double hi) {
  return {lo, hi, true, true};
}
Range positive(double hi) {
  return {0.0, hi, false, true};
}
Range non_negative(double hi) {
  return {0.0, hi, true, true};
}
Range any_finite() {
  return {-kInf, kInf, false, false};
}

std::string format_number(double v) {
  return shortest_text(v);
}

std::string format_number(float v) {
  return shortest_text(v);
}

Field::Field(YAML::Node node, std::string path, const Origin* origin)
    : node_(std::move(node)),
      path_(std::move(path)),
      origin_(origin),
      mark_(node_.IsDefined() ? node_.Mark() : YAML::Mark::null_mark()) {}

Field Field::child(std::string_view key, YAML::Node value, const YAML::Mark& key_mark) const {
  Field f(std::move(value), child_path(path_, key), origin_);
  f.mark_ = key_mark;
  return f;
}

void Field::fail(std::string_view message) const {
  if (const AppliedOverride* o = override_covering(*origin_, path_)) {
    throw_input_error(origin_->file, 0, "override '" + o->text + "': " + path_, message);
  }
  throw_input_error(origin_->file, mark_.is_null() ? 0 : mark_.line + 1,
                    path_.empty() ? "(top level)" : path_, message);
}

void Field::expected(std::string_view expected) const {
  fail("expected " + std::string(expected) + ", got " + describe_value());
}

std::string Field::describe_value() const {
  if (is_null()) return "nothing";
  if (node_.IsSequence()) return "a list";
  if (node_.IsMap()) return "a map";
  return "'" + node_.Scalar() + "'";
}

double Field::number(const Range& range) const {
  return parse_number<double>(*this, range);
}

float Field::number_f(const Range& range) const {
  return parse_number<float>(*this, range);
}

int Field::integer(int lo, int hi, std::string_view limit) const {
  std::string what = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!limit.empty()) what += " (" + std::to_string(hi) + ": " + std::string(limit) + ")";
  long long v = 0;
  if (!is_scalar() || !parse_exact(node_.Scalar(), v) || v < lo || v > hi) expected(what);
  return static_cast<int>(v);
}

std::uint64_t Field::unsigned64() const {
  std::uint64_t v = 0;
  if (!is_scalar() || node_.Scalar().starts_with('-') || !parse_exact(node_.Scalar(), v)) {
    expected("an integer in [0, 2^64 - 1]");
  }
  return v;
}

bool Field::boolean() const {
  bool v = false;
  if (!is_scalar() || !YAML::convert<bool>::decode(node_, v)) expected("true or false");
  return v;
}

std::string Field::text() const {
  if (!is_scalar() || node_.Scalar().empty()) expected("a non-empty text");
  return node_.Scalar();
}

std::vector<Field> Field::items(std::size_t min, std::size_t max) const {
  const auto count_text = [&] {
    if (min == max) return std::to_string(min) + " items";
    return std::to_string(min) + " to " + std::to_string(max) + " items";
  };
  if (!is_sequence()) expected("a list of " + count_text());
  if (node_.size() < min || node_.size() > max) {
    fail("expected a list of " + count_text() + ", got " + std::to_string(node_.size()));
  }
  std::vector<Field> out;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    out.emplace_back(node_[i], path_ + "[" + std::to_string(i) + "]", origin_);
  }
  return out;
}

Eigen::Vector3d Field::vector3(const Range& range) const {
  const auto xs = items(3, 3);
  return {xs[0].number(range), xs[1].number(range), xs[2].number(range)};
}

Eigen::MatrixXd Field::matrix(int rows, int cols) const {
  const auto rs = items(rows, rows);
  Eigen::MatrixXd m(rows, cols);
  for (int r = 0; r < rows; ++r) {
    const auto cs = rs[r].items(cols, cols);
    for (int c = 0; c < cols; ++c) m(r, c) = cs[c].number(any_finite());
  }
  return m;
}

Map::Map(const Field& field) : field_(field) {
  if (field.is_null()) return;
  if (!field.is_map()) field.expected("a map of keys");
  for (const auto& kv : field.node()) {
    const std::string key = kv.first.Scalar();
    const Field value = field.child(key, kv.second, kv.first.Mark());
    if (find(key)) value.fail("duplicate key");
    entries_.push_back({key, value});
  }
}

Map::Entry* Map::find(std::string_view key) {
  for (Entry& e : entries_) {
    if (e.key == key) return &e;
  }
  return nullptr;
}

bool Map::has(std::string_view key) {
  if (std::find(asked_.begin(), asked_.end(), key) == asked_.end()) asked_.emplace_back(key);
  return find(key) != nullptr;
}

std::optional<Field> Map::take(std::string_view key) {
  if (!has(key)) return std::nullopt;
  Entry* e = find(key);
  e->taken = true;
  return e->value;
}

Field Map::require(std::string_view key) {
  if (auto f = take(key)) return *f;
  field_.fail("missing key '" + std::string(key) + "'");
}

void Map::finish() const {
  for (const Entry& e : entries_) {
    if (e.taken) continue;
    std::string allowed;
    for (const std::string& k : asked_) allowed += (allowed.empty() ? "" : ", ") + k;
    e.value.fail(allowed.empty() ? "unknown key (no keys are allowed here)"
                                 : "unknown key (expected one of: " + allowed + ")");
  }
}

}  // namespace simcap::yaml
