#include "scenes/yaml_overrides.h"

#include <cctype>
#include <charconv>
#include <variant>

#include "core/error.h"

namespace simcap::yaml {

namespace {

using Segment = std::variant<std::string, std::size_t>;  // map key or list index

[[noreturn]] void fail(const Origin& origin, const std::string& text, std::string_view message) {
  throw_input_error(origin.file, 0, "override '" + text + "'", message);
}

bool is_key_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// "actors[0].motion.speed" -> {"actors", 0, "motion", "speed"}; empty on a syntax error.
std::vector<Segment> parse_path(std::string_view path) {
  std::vector<Segment> out;
  std::size_t i = 0;
  while (i < path.size()) {
    const std::size_t start = i;
    while (i < path.size() && is_key_char(path[i])) ++i;
    if (i == start) return {};
    out.emplace_back(std::string(path.substr(start, i - start)));
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      if (close == std::string_view::npos) return {};
      std::size_t index = 0;
      const char* first = path.data() + i + 1;
      const char* last = path.data() + close;
      const auto [ptr, ec] = std::from_chars(first, last, index);
      if (first == last || ec != std::errc() || ptr != last) return {};
      out.emplace_back(index);
      i = close + 1;
    }
    if (i == path.size()) break;
    if (path[i] != '.' || i + 1 == path.size()) return {};
    ++i;
  }
  return out;
}

std::string format_path(const std::vector<Segment>& segments, std::size_t count) {
  std::string out;
  for (std::size_t s = 0; s < count; ++s) {
    if (const auto* key = std::get_if<std::string>(&segments[s])) {
      out += (out.empty() ? "" : ".") + *key;
    } else {
      out += "[" + std::to_string(std::get<std::size_t>(segments[s])) + "]";
    }
  }
  return out;
}

std::string kind_of(const YAML::Node& node) {
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "a single value";
}

}  // namespace

void apply_overrides(YAML::Node& root, const std::vector<std::string>& overrides, Origin& origin) {
  // An empty file parses to a null node that owns no storage; make it a map that overrides can
  // add keys to.
  if (!overrides.empty() && root.IsNull()) root.reset(YAML::Node(YAML::NodeType::Map));
  for (const std::string& text : overrides) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) fail(origin, text, "expected key.path=value");
    const std::vector<Segment> path = parse_path(std::string_view(text).substr(0, eq));
    if (path.empty()) {
      fail(origin, text,
           "expected a key path like render.frames or actors[0].motion.speed before '='");
    }
    YAML::Node value;
    try {
      value = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      fail(origin, text, "the value is not valid YAML: " + e.msg);
    }

    YAML::Node node = root;
    for (std::size_t s = 0; s < path.size(); ++s) {
      const std::string where = s == 0 ? "the top level" : "'" + format_path(path, s) + "'";
      const bool last = s + 1 == path.size();
      if (const auto* key = std::get_if<std::string>(&path[s])) {
        if (node.IsDefined() && !node.IsNull() && !node.IsMap()) {
          fail(origin, text, where + " is " + kind_of(node) + ", not a map");
        }
        if (last) {
          node[*key] = value;
        } else {
          node.reset(node[*key]);
        }
      } else {
        const std::size_t index = std::get<std::size_t>(path[s]);
        if (!node.IsSequence()) {
          fail(origin, text,
               where + " is " + (node.IsDefined() && !node.IsNull() ? kind_of(node) : "absent") +
                   ", not a list");
        }
        if (index >= node.size()) {
          fail(origin, text,
               "index " + std::to_string(index) + " is out of range: " + where + " has " +
                   std::to_string(node.size()) + " items");
        }
        if (last) {
          node[index] = value;
        } else {
          node.reset(node[index]);
        }
      }
    }
    origin.overrides.push_back({format_path(path, path.size()), text});
  }
}

}  // namespace simcap::yaml
