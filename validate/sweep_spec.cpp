#include "validate/sweep_spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>

#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

template <typename T>
std::optional<T> parse_number(const std::string& text) {
  T v{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

int line_of(const YAML::Node& node) {
  return node.Mark().line + 1;
}

std::string scalar(const YAML::Node& node, const fs::path& file, const std::string& key) {
  if (!node.IsScalar()) throw_input_error(file, line_of(node), key, "expected a single value");
  return node.Scalar();
}

// A value as YAML text: scalars as written, lists and maps in flow style ("[6, 3, 6]"), which
// is the form scene overrides take.
std::string value_text(const YAML::Node& node, const fs::path& file, const std::string& key) {
  if (node.IsScalar()) return node.Scalar();
  if (!node.IsSequence() && !node.IsMap()) {
    throw_input_error(file, line_of(node), key, "expected a value");
  }
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

fs::path existing_file(const SweepSetting& s, const fs::path& dir, const fs::path& file) {
  const fs::path p = (dir / s.value).lexically_normal();
  std::error_code ec;  // a name too long for the system is no such file either
  if (!fs::is_regular_file(p, ec)) {
    throw_input_error(file, s.line, s.key, "no such file: " + p.string());
  }
  return p;
}

void apply(LoopConfig& c, const SweepSetting& s, const fs::path& dir, const fs::path& file) {
  if (s.key == "scene") {
    c.scene = existing_file(s, dir, file);
  } else if (s.key == "motion") {
    c.motion = existing_file(s, dir, file);
  } else if (s.key == "frames") {
    const auto v = parse_number<int>(s.value);
    if (!v || *v < 1) throw_input_error(file, s.line, s.key, "expected a positive integer");
    c.frames = *v;
  } else if (s.key == "seed") {
    const auto v = parse_number<std::uint64_t>(s.value);
    if (!v) throw_input_error(file, s.line, s.key, "expected a non-negative integer");
    c.seed = *v;
  } else if (s.key == "failure_threshold_mm") {
    const auto v = parse_number<double>(s.value);
    if (!v || !(*v > 0)) throw_input_error(file, s.line, s.key, "expected a positive number");
    c.failure_threshold_mm = *v;
  } else if (s.key == "detector" || s.key == "detector.name") {
    c.detector.name = s.value;
    c.detector.line = s.line;
  } else if (s.key == "detector.noise_px") {
    const auto v = parse_number<double>(s.value);
    if (!v || !(*v >= 0)) throw_input_error(file, s.line, s.key, "expected a number >= 0 (pixels)");
    c.detector.noise_px = *v;
  } else if (s.key == "detector.seed") {
    const auto v = parse_number<std::uint64_t>(s.value);
    if (!v) throw_input_error(file, s.line, s.key, "expected a non-negative integer");
    c.detector.seed = *v;
  } else if (s.key.rfind("detector.", 0) == 0) {
    throw_input_error(file, s.line, s.key, "unknown detector key; expected name, noise_px or seed");
  } else if (s.key.rfind("track.", 0) == 0) {
    if (s.key.size() == 6) throw_input_error(file, s.line, s.key, "expected track.<option>");
    c.track_options.emplace_back(s.key.substr(6), s.value);
    c.track_option_lines.push_back(s.line);
  } else if (s.key == "title" || s.key == "set" || s.key == "track" || s.key == "vary" ||
             s.key == "label" || s.key.empty() || s.key.find('=') != std::string::npos) {
    throw_input_error(file, s.line, s.key,
                      "cannot be varied; expected scene, frames, seed, motion, "
                      "failure_threshold_mm, track.<option>, detector.<key> or a scene key such "
                      "as rig.count");
  } else {
    c.scene_overrides.push_back(s.key + "=" + s.value);
    c.scene_override_lines.push_back(s.line);
  }
}

SweepAxis parameter_axis(const YAML::Node& node, const fs::path& file) {
  SweepAxis axis;
  const std::string parameter = scalar(node["parameter"], file, "parameter");
  axis.name = node["name"] ? scalar(node["name"], file, "name") : parameter;
  const YAML::Node values = node["values"];
  if (!values || !values.IsSequence() || values.size() == 0) {
    throw_input_error(file, line_of(node), "values", "expected a list of values for " + parameter);
  }
  for (const auto& v : values) {
    const std::string text = value_text(v, file, "values");
    axis.labels.push_back(text);
    axis.settings.push_back({{parameter, text, line_of(v)}});
  }
  return axis;
}

SweepAxis case_axis(const YAML::Node& node, const fs::path& file) {
  SweepAxis axis;
  axis.name = node["name"] ? scalar(node["name"], file, "name") : "case";
  const YAML::Node cases = node["cases"];
  if (!cases.IsSequence() || cases.size() == 0) {
    throw_input_error(file, line_of(node), "cases", "expected a list of cases");
  }
  for (const auto& c : cases) {
    if (!c.IsMap()) throw_input_error(file, line_of(c), "cases", "expected a map of settings");
    std::string label, joined;
    std::vector<SweepSetting> settings;
    for (const auto& kv : c) {
      const std::string key = kv.first.as<std::string>();
      const std::string value = value_text(kv.second, file, key);
      if (key == "label") {
        label = value;
        continue;
      }
      settings.push_back({key, value, line_of(kv.second)});
      joined += (joined.empty() ? "" : " ") + key + "=" + value;
    }
    if (settings.empty()) throw_input_error(file, line_of(c), "cases", "a case sets nothing");
    axis.labels.push_back(label.empty() ? joined : label);
    axis.settings.push_back(std::move(settings));
  }
  return axis;
}

SweepAxis axis_of(const YAML::Node& node, const fs::path& file) {
  if (!node.IsMap()) {
    throw_input_error(file, line_of(node), "vary", "expected a map with parameter and values");
  }
  for (const auto& kv : node) {
    const std::string key = kv.first.as<std::string>();
    if (key != "name" && key != "parameter" && key != "values" && key != "cases") {
      throw_input_error(file, line_of(kv.first), "vary." + key,
                        "unknown key; expected name, parameter and values, or name and cases");
    }
  }
  if (node["parameter"] && !node["cases"]) return parameter_axis(node, file);
  if (node["cases"] && !node["parameter"] && !node["values"]) return case_axis(node, file);
  throw_input_error(file, line_of(node), "vary", "expected either parameter and values, or cases");
}

}  // namespace

bool SweepAxis::numeric() const {
  for (const auto& l : labels) {
    if (!parse_number<double>(l)) return false;
  }
  return !labels.empty();
}

SweepSpec load_sweep(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw_input_error(file, 0, "", "no such sweep file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(file.string());
  } catch (const YAML::Exception& e) {
    throw_input_error(file, e.mark.line + 1, "", e.msg);
  }
  if (!root.IsMap()) {
    throw_input_error(file, 1, "", "expected a map with scene, frames, track and vary");
  }
  SweepSpec spec;
  spec.file = file;
  const fs::path dir = file.parent_path();
  try {
    for (const auto& kv : root) {
      const std::string key = kv.first.as<std::string>();
      const YAML::Node& v = kv.second;
      if (key == "title") {
        spec.title = scalar(v, file, key);
      } else if (key == "scene" || key == "frames" || key == "seed" || key == "motion" ||
                 key == "failure_threshold_mm") {
        apply(spec.base, {key, scalar(v, file, key), line_of(v)}, dir, file);
      } else if (key == "detector" && v.IsScalar()) {
        apply(spec.base, {key, v.Scalar(), line_of(v)}, dir, file);
      } else if (key == "set" || key == "track" || key == "detector") {
        if (!v.IsMap()) throw_input_error(file, line_of(v), key, "expected a map of key: value");
        for (const auto& s : v) {
          const std::string name = s.first.as<std::string>();
          const std::string full = key == "set" ? name : key + "." + name;
          apply(spec.base, {full, value_text(s.second, file, key + "." + name), line_of(s.second)},
                dir, file);
        }
      } else if (key == "vary") {
        if (!v.IsSequence() || v.size() == 0) {
          throw_input_error(file, line_of(v), key, "expected a list of parameters to vary");
        }
        for (const auto& a : v) spec.axes.push_back(axis_of(a, file));
      } else {
        throw_input_error(file, line_of(kv.first), key,
                          "unknown key; expected title, scene, frames, seed, motion, set, track, "
                          "detector, failure_threshold_mm or vary");
      }
    }
  } catch (const YAML::Exception& e) {
    throw_input_error(file, e.mark.line + 1, "", e.msg);
  }
  if (spec.axes.empty()) throw_input_error(file, 0, "vary", "missing; expected what to vary");
  std::size_t points = 1;
  std::string sizes;
  for (const auto& axis : spec.axes) {
    points = std::min(points * axis.labels.size(), kMaxSweepPoints + 1);
    sizes += (sizes.empty() ? "" : " x ") + std::to_string(axis.labels.size());
  }
  if (points > kMaxSweepPoints) {
    throw_input_error(file, 0, "vary",
                      "the axes make more than " + std::to_string(kMaxSweepPoints) + " points (" +
                          sizes + "), simcap's limit for one sweep; split it");
  }
  // Settings are checked now, so that a bad value stops the sweep before any point runs.
  for (const auto& axis : spec.axes) {
    for (const auto& settings : axis.settings) {
      LoopConfig probe = spec.base;
      for (const auto& s : settings) apply(probe, s, dir, file);
    }
  }
  const bool scene_varied = std::any_of(spec.axes.begin(), spec.axes.end(), [](const auto& a) {
    return std::any_of(a.settings.begin(), a.settings.end(), [](const auto& list) {
      return std::any_of(list.begin(), list.end(), [](const auto& s) { return s.key == "scene"; });
    });
  });
  if (spec.base.scene.empty() && !scene_varied) {
    throw_input_error(file, 0, "scene", "missing; expected the scene file to render");
  }
  return spec;
}

std::vector<SweepPoint> sweep_points(const SweepSpec& spec) {
  std::vector<SweepPoint> points = {{{}, spec.base}};
  const fs::path dir = spec.file.parent_path();
  for (const auto& axis : spec.axes) {
    std::vector<SweepPoint> next;
    for (const auto& p : points) {
      for (size_t i = 0; i < axis.labels.size(); ++i) {
        SweepPoint q = p;
        q.labels.push_back(axis.labels[i]);
        for (const auto& s : axis.settings[i]) apply(q.config, s, dir, spec.file);
        next.push_back(std::move(q));
      }
    }
    points = std::move(next);
  }
  return points;
}

}  // namespace simcap
