#include "models/bvh.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <unordered_set>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/limits.h"

namespace simcap {
namespace {

struct Token {
  std::string_view text;
  int line = 0;
};

// Whitespace-separated tokens with their 1-based line numbers; LF, CRLF and lone CR end lines.
std::vector<Token> tokenize(std::string_view text) {
  std::vector<Token> tokens;
  int line = 1;
  size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      ++line;
      ++i;
    } else if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {
      ++i;
    } else {
      const size_t start = i;
      while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
      tokens.push_back({text.substr(start, i - start), line});
    }
  }
  return tokens;
}

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

constexpr std::array<std::string_view, 6> kChannelNames = {"Xposition", "Yposition", "Zposition",
                                                           "Xrotation", "Yrotation", "Zrotation"};

bool is_position(BvhChannel c) {
  return c == BvhChannel::x_position || c == BvhChannel::y_position || c == BvhChannel::z_position;
}

Eigen::Vector3d channel_axis(BvhChannel c) {
  switch (c) {
    case BvhChannel::x_position:
    case BvhChannel::x_rotation:
      return Eigen::Vector3d::UnitX();
    case BvhChannel::y_position:
    case BvhChannel::y_rotation:
      return Eigen::Vector3d::UnitY();
    default:
      return Eigen::Vector3d::UnitZ();
  }
}

class Parser {
 public:
  Parser(std::string_view text, const std::filesystem::path& file)
      : tokens_(tokenize(text)), file_(file) {}

  BvhClip parse() {
    BvhClip clip;
    clip.file = file_;
    keyword("HIERARCHY");
    keyword("ROOT");
    parse_hierarchy(clip);
    if (at_end()) {
      fail(last_line(), "expected MOTION after the hierarchy, got the end of the file");
    }
    if (iequals(peek().text, "ROOT")) fail(peek().line, "only one ROOT is supported");
    keyword("MOTION");
    keyword("Frames:");
    const Token& frames_token = next("the frame count");
    const long frames = integer(frames_token, "frame count");
    if (frames < 1)
      fail(frames_token.line, "expected at least 1 frame, got " + std::to_string(frames));
    if (frames > limits::kMaxFrames) {
      fail(frames_token.line, "Frames: " + std::to_string(frames) +
                                  " is more than simcap's largest frame count, " +
                                  std::to_string(limits::kMaxFrames));
    }
    keyword("Frame");
    keyword("Time:");
    const Token& time_token = next("the frame time in seconds");
    clip.frame_time = number(time_token, "frame time");
    if (!(clip.frame_time > 0)) fail(time_token.line, "expected a positive frame time in seconds");
    parse_frames(clip, frames, frames_token.line);
    return clip;
  }

 private:
  bool at_end() const { return pos_ >= tokens_.size(); }
  const Token& peek() const { return tokens_[pos_]; }
  int last_line() const { return tokens_.empty() ? 1 : tokens_.back().line; }

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw_input_error(file_, line, "", message);
  }

  const Token& next(const std::string& expected) {
    if (at_end()) fail(last_line(), "unexpected end of the file: expected " + expected);
    return tokens_[pos_++];
  }

  void keyword(std::string_view word) {
    const Token& t = next("'" + std::string(word) + "'");
    if (!iequals(t.text, word)) {
      fail(t.line, "expected '" + std::string(word) + "', got '" + std::string(t.text) + "'");
    }
  }

  double number(const Token& t, const std::string& what) const {
    std::string_view s = t.text;
    if (s.size() > 1 && s[0] == '+') s.remove_prefix(1);
    double v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
      fail(t.line, what + ": expected a number, got '" + std::string(t.text) + "'");
    }
    return v;
  }

  long integer(const Token& t, const std::string& what) const {
    long v = 0;
    const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (ec != std::errc() || end != t.text.data() + t.text.size()) {
      fail(t.line, what + ": expected an integer, got '" + std::string(t.text) + "'");
    }
    return v;
  }

  Eigen::Vector3d offset(const std::string& joint) {
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) {
      v[k] = number(next("3 OFFSET values for '" + joint + "'"), "OFFSET of '" + joint + "'");
    }
    return v;
  }

  // `name`, or the first of name2, name3, ... not taken. Each base name remembers its last
  // suffix, so that many end sites under one joint cost linear time.
  std::string unique_name(const std::string& name) {
    if (!names_.contains(name)) return name;
    int& k = last_suffix_[name];
    while (true) {
      k = std::max(k + 1, 2);
      std::string candidate = name + std::to_string(k);
      if (!names_.contains(candidate)) return candidate;
    }
  }

  void add_name(BvhClip& clip, BvhJoint joint) {
    names_.insert(joint.name);
    clip.joints.push_back(std::move(joint));
  }

  int add_joint(BvhClip& clip, int parent) {
    const Token& t = next("a joint name");
    if (t.text == "{" || t.text == "}") {
      fail(t.line, "expected a joint name, got '" + std::string(t.text) + "'");
    }
    BvhJoint joint;
    joint.name = std::string(t.text);
    if (names_.contains(joint.name)) fail(t.line, "joint name '" + joint.name + "' used twice");
    joint.parent = parent;
    add_name(clip, std::move(joint));
    keyword("{");
    return static_cast<int>(clip.joints.size()) - 1;
  }

  void parse_channels(BvhClip& clip, int j) {
    BvhJoint& joint = clip.joints[j];
    const Token& count_token = next("the channel count of '" + joint.name + "'");
    const long count = integer(count_token, "CHANNELS of '" + joint.name + "'");
    if (count < 0 || count > 6) {
      fail(count_token.line, "CHANNELS of '" + joint.name + "': expected 0 to 6 channels, got " +
                                 std::to_string(count));
    }
    joint.first_channel = clip.channel_count;
    for (long k = 0; k < count; ++k) {
      const Token& t = next(std::to_string(count) + " channel names for '" + joint.name + "'");
      const auto it = std::find_if(kChannelNames.begin(), kChannelNames.end(),
                                   [&](std::string_view n) { return iequals(n, t.text); });
      if (it == kChannelNames.end()) {
        fail(t.line, "CHANNELS of '" + joint.name + "': expected " + std::to_string(count) +
                         " channel names (Xposition, Yposition, Zposition, Xrotation, Yrotation "
                         "or Zrotation), got '" +
                         std::string(t.text) + "'");
      }
      joint.channels.push_back(static_cast<BvhChannel>(it - kChannelNames.begin()));
    }
    clip.channel_count += static_cast<int>(count);
  }

  // Reads from after "ROOT" to the root's closing brace. Iterative, so deep or malformed
  // nesting cannot exhaust the stack.
  void parse_hierarchy(BvhClip& clip) {
    struct Open {
      int joint;
      bool has_offset = false, has_channels = false;
    };
    std::vector<Open> open;
    open.push_back({add_joint(clip, -1)});
    while (!open.empty()) {
      Open& top = open.back();
      const std::string name = clip.joints[top.joint].name;
      const Token& t = next("'}' closing joint '" + name + "'");
      if (iequals(t.text, "OFFSET")) {
        if (top.has_offset) fail(t.line, "joint '" + name + "' has a second OFFSET");
        clip.joints[top.joint].offset = offset(name);
        top.has_offset = true;
      } else if (iequals(t.text, "CHANNELS")) {
        if (!top.has_offset) fail(t.line, "joint '" + name + "': expected OFFSET before CHANNELS");
        if (top.has_channels) fail(t.line, "joint '" + name + "' has a second CHANNELS");
        parse_channels(clip, top.joint);
        top.has_channels = true;
      } else if (iequals(t.text, "JOINT") || iequals(t.text, "End")) {
        if (!top.has_offset || !top.has_channels) {
          fail(t.line, "joint '" + name + "': expected OFFSET and CHANNELS before its children");
        }
        if (iequals(t.text, "JOINT")) {
          open.push_back({add_joint(clip, top.joint)});
        } else {
          keyword("Site");
          keyword("{");
          keyword("OFFSET");
          BvhJoint site;
          site.name = unique_name(name + "_End");
          site.parent = top.joint;
          site.is_end_site = true;
          site.offset = offset(site.name);
          site.first_channel = clip.channel_count;
          add_name(clip, std::move(site));
          keyword("}");
        }
      } else if (t.text == "}") {
        if (!top.has_offset || !top.has_channels) {
          fail(t.line, "joint '" + name + "': expected OFFSET and CHANNELS before '}'");
        }
        open.pop_back();
      } else {
        fail(t.line, "in joint '" + name +
                         "': expected OFFSET, CHANNELS, JOINT, End Site or '}', got '" +
                         std::string(t.text) + "'");
      }
    }
    if (clip.channel_count == 0) fail(last_line(), "the hierarchy has no channels");
  }

  // One frame per line, each with exactly channel_count values.
  void parse_frames(BvhClip& clip, long frames, int frames_line) {
    const size_t stride = clip.channel_count;
    clip.values.reserve(std::min(static_cast<size_t>(frames) * stride, tokens_.size() - pos_));
    long frame = 0;
    while (!at_end()) {
      const int line = peek().line;
      if (frame == frames) {
        fail(line, "more frames than the " + std::to_string(frames) + " that 'Frames:' (line " +
                       std::to_string(frames_line) + ") announces");
      }
      size_t count = 0;
      while (!at_end() && peek().line == line) {
        const Token& t = tokens_[pos_++];
        ++count;
        if (count <= stride) {
          clip.values.push_back(
              number(t, "frame " + std::to_string(frame) + ", value " + std::to_string(count)));
        }
      }
      if (count != stride) {
        fail(line, "frame " + std::to_string(frame) + ": expected " + std::to_string(stride) +
                       " values (one per channel of the hierarchy), got " + std::to_string(count));
      }
      ++frame;
    }
    if (frame != frames) {
      fail(last_line(), "expected " + std::to_string(frames) + " frames ('Frames:' on line " +
                            std::to_string(frames_line) + "), the file ends after " +
                            std::to_string(frame));
    }
  }

  std::vector<Token> tokens_;
  size_t pos_ = 0;
  std::filesystem::path file_;
  std::unordered_set<std::string> names_;  // of the joints and end sites so far
  std::unordered_map<std::string, int> last_suffix_;
};

// The unit that makes the rest skeleton's largest extent closest (in ratio) to an adult's 1.7 m.
double detect_metres_per_unit(const BvhClip& clip) {
  const auto rest = bvh_joint_positions(clip, -1);
  Eigen::Vector3d lo = rest[0], hi = rest[0];
  for (const auto& p : rest) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).maxCoeff();
  if (!(extent > 0)) return 1.0;
  const double candidates[] = {1.0, 0.01, 0.001, 0.0254, kCmuMetresPerUnit};
  double best = 1.0, best_error = INFINITY;
  for (double c : candidates) {
    const double error = std::abs(std::log(extent * c / 1.7));
    if (error < best_error) {
      best_error = error;
      best = c;
    }
  }
  return best;
}

void convert_units(BvhClip& clip, double metres_per_unit) {
  clip.metres_per_unit = metres_per_unit;
  std::vector<bool> position(clip.channel_count, false);
  for (auto& joint : clip.joints) {
    joint.offset *= metres_per_unit;
    for (size_t k = 0; k < joint.channels.size(); ++k) {
      position[joint.first_channel + k] = is_position(joint.channels[k]);
    }
  }
  for (size_t i = 0; i < clip.values.size(); ++i) {
    if (position[i % clip.channel_count]) clip.values[i] *= metres_per_unit;
  }
}

}  // namespace

std::string_view bvh_channel_name(BvhChannel channel) {
  return kChannelNames[static_cast<int>(channel)];
}

int BvhClip::find(std::string_view name) const {
  for (size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::vector<int> BvhClip::children(int joint) const {
  std::vector<int> out;
  for (size_t i = joint + 1; i < joints.size(); ++i) {
    if (joints[i].parent == joint) out.push_back(static_cast<int>(i));
  }
  return out;
}

BvhClip parse_bvh(std::string_view text, const std::filesystem::path& file,
                  const BvhReadOptions& options) {
  BvhClip clip = Parser(text, file).parse();
  if (options.metres_per_unit < 0 || !std::isfinite(options.metres_per_unit)) {
    throw Error("metres per BVH unit must be positive (or 0 to detect it), got " +
                std::to_string(options.metres_per_unit));
  }
  clip.units_detected = options.metres_per_unit == 0;
  convert_units(clip, clip.units_detected ? detect_metres_per_unit(clip) : options.metres_per_unit);
  return clip;
}

BvhClip read_bvh(const std::filesystem::path& path, const BvhReadOptions& options) {
  return parse_bvh(read_text(path), path, options);
}

Eigen::Isometry3d bvh_local_transform(const BvhClip& clip, int joint, int frame) {
  const BvhJoint& j = clip.joints[joint];
  Eigen::Isometry3d local = Eigen::Isometry3d::Identity();
  local.translation() = j.offset;
  if (frame < 0) return local;
  const double* values = clip.values.data() + static_cast<size_t>(frame) * clip.channel_count;
  for (size_t k = 0; k < j.channels.size(); ++k) {
    const double v = values[j.first_channel + k];
    const Eigen::Vector3d axis = channel_axis(j.channels[k]);
    if (is_position(j.channels[k])) {
      local.translate(v * axis);
    } else {
      local.rotate(Eigen::AngleAxisd(v * std::numbers::pi / 180.0, axis));
    }
  }
  return local;
}

std::vector<Eigen::Isometry3d> bvh_forward_kinematics(const BvhClip& clip, int frame) {
  if (frame >= clip.frame_count()) {
    throw Error(clip.file.string() + ": frame " + std::to_string(frame) +
                " requested, the clip has " + std::to_string(clip.frame_count()));
  }
  std::vector<Eigen::Isometry3d> world(clip.joints.size());
  for (size_t j = 0; j < clip.joints.size(); ++j) {
    const Eigen::Isometry3d local = bvh_local_transform(clip, static_cast<int>(j), frame);
    const int p = clip.joints[j].parent;
    world[j] = p < 0 ? local : world[p] * local;
  }
  return world;
}

std::vector<Eigen::Vector3d> bvh_joint_positions(const BvhClip& clip, int frame) {
  const auto world = bvh_forward_kinematics(clip, frame);
  std::vector<Eigen::Vector3d> out(world.size());
  for (size_t j = 0; j < world.size(); ++j) out[j] = world[j].translation();
  return out;
}

}  // namespace simcap
