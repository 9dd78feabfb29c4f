#include "collect/collection_spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scenes/scene.h"
#include "scenes/yaml_field.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

using yaml::Field;
using yaml::Map;

constexpr int kMaxCount = 100'000'000;
constexpr std::size_t kMaxChoices = 1'000'000;

int line_of(const Field& f) {
  return f.node().Mark().line + 1;
}

// A value as YAML text that reads back as the same value in an override ("#aa2222" quoted,
// lists in flow style).
std::string yaml_text(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

// A value as the index shows it: a quoted scalar ("#aa2222") without its quotes.
std::string display_text(const std::string& yaml) {
  const YAML::Node node = YAML::Load(yaml);
  return node.IsScalar() ? node.Scalar() : yaml;
}

std::optional<long long> integer_of(const std::string& text) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

// A fixed value, a list of choices or {uniform: [lo, hi]}.
CollectionParam read_param(const Field& f, std::string key) {
  CollectionParam p;
  p.key = std::move(key);
  p.line = line_of(f);
  if (f.is_map()) {
    Map m(f);
    const auto ends = m.require("uniform").items(2, 2);
    m.finish();
    p.is_range = true;
    p.lo = ends[0].number(yaml::any_finite());
    p.hi = ends[1].number(yaml::any_finite());
    p.integer = integer_of(ends[0].text()) && integer_of(ends[1].text());
    if (p.lo > p.hi) {
      f.fail("the range [" + ends[0].text() + ", " + ends[1].text() + "] is empty (lo > hi)");
    }
    return p;
  }
  if (f.is_sequence()) {
    for (const Field& c : f.items(1, kMaxChoices)) p.choices.push_back(yaml_text(c.node()));
    return p;
  }
  if (f.is_null()) f.expected("a value, a list of choices or {uniform: [lo, hi]}");
  p.choices.push_back(yaml_text(f.node()));
  return p;
}

fs::path existing_path(const Field& f, const fs::path& dir) {
  const fs::path p = fs::absolute(dir / f.text()).lexically_normal();
  if (!fs::exists(p)) f.fail("no such file or folder: " + p.string());
  return p;
}

std::string quoted(const fs::path& p) {
  return yaml_text(YAML::Node(p.string()));
}

std::string lower_extension(const fs::path& p) {
  std::string ext = p.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
  return ext;
}

// A motion clip of a folder: a BVH file, or an AMC file with the ASF skeleton it moves.
struct FolderClip {
  fs::path file, asf;
};

// The ASF of `amc` in a folder holding `asfs`: the folder's only one, else CMU's naming
// (subject 131's 131_01.amc moves 131.asf).
fs::path asf_of(const Field& f, const fs::path& amc, const std::vector<fs::path>& asfs) {
  if (asfs.size() == 1) return asfs.front();
  const std::string stem = amc.stem().string();
  const std::string subject = stem.substr(0, stem.find('_'));
  for (const fs::path& asf : asfs) {
    if (asf.stem().string() == subject) return asf;
  }
  f.fail("no ASF skeleton for " + amc.filename().string() + " in its folder (expected " + subject +
         ".asf, the only *.asf, or an 'asf' key)");
}

// The clips of a motion folder: its .bvh files and its .amc files with their ASF (`asf`, when
// given, for all of them), sorted by name so every process lists them in the same order.
std::vector<FolderClip> folder_clips(const Field& f, const fs::path& dir,
                                     const std::optional<Field>& asf) {
  const fs::path folder = existing_path(f, dir);
  if (!fs::is_directory(folder)) f.fail("not a folder: " + folder.string());
  std::vector<fs::path> bvhs, amcs, asfs;
  for (const auto& e : fs::directory_iterator(folder)) {
    if (!e.is_regular_file()) continue;
    const std::string ext = lower_extension(e.path());
    if (ext == ".bvh") bvhs.push_back(e.path());
    if (ext == ".amc") amcs.push_back(e.path());
    if (ext == ".asf") asfs.push_back(e.path());
  }
  if (asf) asfs = {existing_path(*asf, dir)};
  std::sort(asfs.begin(), asfs.end());
  std::vector<FolderClip> clips;
  for (const fs::path& b : bvhs) clips.push_back({b, {}});
  for (const fs::path& a : amcs) clips.push_back({a, asf_of(f, a, asfs)});
  if (clips.empty()) {
    f.fail("the folder " + folder.string() + " holds no motion clip (*.bvh, or *.amc with *.asf)");
  }
  std::sort(clips.begin(), clips.end(),
            [](const FolderClip& a, const FolderClip& b) { return a.file < b.file; });
  return clips;
}

void read_motion(const Field& f, const fs::path& dir, std::vector<CollectionMotion>& out) {
  Map m(f);
  CollectionMotion motion;
  motion.line = line_of(f);
  auto keep = [&](const char* key, bool as_param) {
    if (auto v = m.take(key)) {
      if (as_param) {
        motion.params.push_back(read_param(*v, key));
      } else {
        motion.fixed.emplace_back(key, yaml_text(v->node()));
      }
    }
  };
  if (auto folder = m.take("folder")) {
    const std::optional<Field> asf = m.take("asf");
    keep("fps", false);
    keep("units", false);
    m.finish();
    for (const FolderClip& clip : folder_clips(*folder, dir, asf)) {
      CollectionMotion one = motion;
      one.label = clip.file.filename().string();
      if (clip.asf.empty()) {
        std::erase_if(one.fixed, [](const auto& kv) { return kv.first == "fps"; });
        one.fixed.insert(one.fixed.begin(), {"bvh", quoted(clip.file)});
      } else {
        one.fixed.insert(one.fixed.begin(),
                         {{"amc", quoted(clip.file)}, {"asf", quoted(clip.asf)}});
      }
      out.push_back(std::move(one));
    }
    return;
  }
  if (auto bvh = m.take("bvh")) {
    const fs::path clip = existing_path(*bvh, dir);
    motion.label = clip.filename().string();
    motion.fixed.emplace_back("bvh", quoted(clip));
    keep("units", false);
  } else if (auto amc = m.take("amc")) {
    const fs::path clip = existing_path(*amc, dir);
    motion.label = clip.filename().string();
    motion.fixed.emplace_back("amc", quoted(clip));
    motion.fixed.emplace_back("asf", quoted(existing_path(m.require("asf"), dir)));
    keep("fps", false);
    keep("units", false);
  } else if (auto kind = m.take("procedural")) {
    motion.label = kind->text();
    motion.fixed.emplace_back("procedural", yaml_text(kind->node()));
    for (const char* key : {"duration", "speed", "radius", "turn_deg"}) keep(key, true);
  } else {
    f.expected(
        "a motion: {bvh: FILE}, {amc: FILE, asf: FILE}, {folder: FOLDER} or "
        "{procedural: KIND, ...}");
  }
  m.finish();
  out.push_back(std::move(motion));
}

// Per-sequence random numbers: SplitMix64, whose output depends only on its seed.
class SequenceRandom {
 public:
  SequenceRandom(std::uint64_t master, int id) : state_(master) {
    state_ ^= next() + static_cast<std::uint64_t>(id);
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

 private:
  std::uint64_t state_;
};

// A range's value: integers uniformly, reals uniformly rounded to 4 decimals (0.1 mm).
std::string draw(const CollectionParam& p, SequenceRandom& random) {
  if (p.integer) {
    const auto span = static_cast<std::uint64_t>(p.hi - p.lo) + 1;
    return std::to_string(static_cast<long long>(p.lo) +
                          static_cast<long long>(random.next() % span));
  }
  const double u = static_cast<double>(random.next() >> 11) * 0x1.0p-53;
  const double v = std::round((p.lo + u * (p.hi - p.lo)) * 1e4) / 1e4;
  return yaml::format_number(std::clamp(v, p.lo, p.hi));
}

// The value of a parameter that is not crossed (fixed, range, or a motion's list).
std::string value_of(const CollectionParam& p, SequenceRandom& random) {
  if (p.is_range) return draw(p, random);
  if (p.choices.size() == 1) return p.choices.front();
  return p.choices[random.next() % p.choices.size()];
}

bool crossed(const CollectionParam& p) {
  return !p.is_range && p.choices.size() > 1;
}

std::string motion_override(const CollectionMotion& m,
                            const std::vector<std::pair<std::string, std::string>>& values) {
  std::string text;
  for (const auto& [k, v] : m.fixed) text += (text.empty() ? "" : ", ") + k + ": " + v;
  for (const auto& [k, v] : values) text += ", " + k + ": " + v;
  return "actors[0].motion={" + text + "}";
}

// Loads the first scene with `overrides` added, so that a value the scenes refuse is reported
// at the spec's line.
void probe(const CollectionSpec& spec, const std::vector<std::string>& overrides, int line,
           const std::string& key) {
  std::vector<std::string> all = spec.set;
  all.insert(all.end(), overrides.begin(), overrides.end());
  try {
    load_scene(spec.scenes.front(), all);
  } catch (const Error& e) {
    throw_input_error(spec.file, line, key, e.what());
  }
}

// Every value a sequence can take (each choice, both ends of each range) against the scenes.
void check_values(const CollectionSpec& spec) {
  for (size_t i = 0; i < spec.scenes.size(); ++i) {
    try {
      load_scene(spec.scenes[i], spec.set);
    } catch (const Error& e) {
      throw_input_error(spec.file, spec.scene_lines[i], "scenes", e.what());
    }
  }
  auto values = [](const CollectionParam& p) {
    return p.is_range
               ? std::vector<std::string>{yaml::format_number(p.lo), yaml::format_number(p.hi)}
               : p.choices;
  };
  for (const auto& p : spec.params) {
    for (const auto& v : values(p)) probe(spec, {p.key + "=" + v}, p.line, p.key);
  }
  for (const auto& m : spec.motions) {
    std::vector<std::pair<std::string, std::string>> firsts;
    for (const auto& p : m.params) firsts.emplace_back(p.key, values(p).front());
    probe(spec, {motion_override(m, firsts)}, m.line, "motions");
    for (const auto& p : m.params) {
      for (const auto& v : values(p)) {
        auto one = firsts;
        for (auto& [k, x] : one) {
          if (k == p.key) x = v;
        }
        probe(spec, {motion_override(m, one)}, p.line, "motions." + p.key);
      }
    }
  }
}

YAML::Node parse_yaml(const fs::path& file, const std::string& text) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw_input_error(file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "not valid YAML: " + e.msg);
  }
}

}  // namespace

CollectionSpec load_collection(const fs::path& file) {
  CollectionSpec spec;
  spec.file = fs::absolute(file).lexically_normal();
  if (!fs::is_regular_file(spec.file)) throw_input_error(spec.file, 0, "", "no such spec file");
  spec.text = read_text(spec.file);
  const fs::path dir = spec.file.parent_path();
  const yaml::Origin origin{spec.file, {}};
  const YAML::Node root = parse_yaml(spec.file, spec.text);
  const Field top(root, "", &origin);
  if (!top.is_map()) top.expected("a collection spec (a map with scenes, motions, frames, ...)");
  Map m(top);
  spec.seed = m.require("seed").unsigned64();
  spec.frames = m.require("frames").integer(1, 1'000'000);
  for (const Field& s : m.require("scenes").items(1, kMaxChoices)) {
    spec.scenes.push_back(existing_path(s, dir));
    spec.scene_lines.push_back(line_of(s));
  }
  if (auto set = m.take("set")) {
    if (!set->is_map()) set->expected("a map of scene key: value");
    for (const auto& kv : set->node()) {
      spec.set.push_back(kv.first.as<std::string>() + "=" + yaml_text(kv.second));
    }
  }
  for (const Field& motion : m.require("motions").items(1, kMaxChoices)) {
    read_motion(motion, dir, spec.motions);
  }
  auto read_group = [&](const char* group, const std::string& prefix,
                        const std::vector<std::string>& keys) {
    std::optional<Field> g = m.take(group);
    if (!g) return false;
    if (!g->is_map()) g->expected("a map of key: value, list of choices or {uniform: [lo, hi]}");
    for (const auto& kv : g->node()) {
      const std::string key = kv.first.as<std::string>();
      const Field value = g->child(key, kv.second, kv.first.Mark());
      if (!keys.empty() && std::find(keys.begin(), keys.end(), key) == keys.end()) {
        value.fail("unknown key; expected " + keys.front() + " or " + keys.back());
      }
      spec.params.push_back(read_param(value, prefix + key));
    }
    return true;
  };
  read_group("bodies", "actors[0].", {});
  read_group("colors", "actors[0].colors.", {});
  read_group("vary", "", {});
  spec.camera_jitter = read_group("camera_jitter", "rig.jitter.", {"position_m", "rotation_deg"});
  long long combinations = static_cast<long long>(spec.scenes.size() * spec.motions.size());
  for (const auto& p : spec.params) {
    if (crossed(p)) combinations = std::min<long long>(combinations * p.choices.size(), kMaxCount);
  }
  if (auto count = m.take("count")) {
    spec.count = count->integer(1, kMaxCount);
  } else {
    spec.count = static_cast<int>(combinations);
  }
  m.finish();
  check_values(spec);
  return spec;
}

CollectionSequence collection_sequence(const CollectionSpec& spec, int id) {
  CollectionSequence s;
  s.id = id;
  SequenceRandom random(spec.seed, id);
  s.seed = random.next();
  // Mixed radix over the crossed lists, the last one fastest.
  std::vector<size_t> sizes = {spec.scenes.size(), spec.motions.size()};
  for (const auto& p : spec.params) {
    if (crossed(p)) sizes.push_back(p.choices.size());
  }
  std::vector<size_t> pick(sizes.size());
  auto rest = static_cast<std::uint64_t>(id);
  for (size_t i = sizes.size(); i-- > 0;) {
    pick[i] = rest % sizes[i];
    rest /= sizes[i];
  }
  s.scene = spec.scenes[pick[0]];
  const CollectionMotion& motion = spec.motions[pick[1]];
  s.motion = motion.label;
  s.overrides = spec.set;
  s.parameters.emplace_back("scene", s.scene.lexically_relative(spec.file.parent_path()).string());
  s.parameters.emplace_back("motion", motion.label);
  std::vector<std::pair<std::string, std::string>> motion_values;
  for (const auto& p : motion.params) {
    motion_values.emplace_back(p.key, value_of(p, random));
    s.parameters.emplace_back("motion." + p.key, display_text(motion_values.back().second));
  }
  s.overrides.push_back(motion_override(motion, motion_values));
  size_t axis = 2;
  for (const auto& p : spec.params) {
    const std::string v = crossed(p) ? p.choices[pick[axis++]] : value_of(p, random);
    s.parameters.emplace_back(p.key, display_text(v));
    s.overrides.push_back(p.key + "=" + v);
  }
  // The cameras' directions and amounts within the ranges: from the sequence's render seed.
  if (spec.camera_jitter) s.overrides.push_back("rig.jitter.seed=" + std::to_string(s.seed));
  return s;
}

}  // namespace simcap
