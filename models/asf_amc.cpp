#include "models/asf_amc.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <numbers>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/limits.h"
#include "models/bvh_export.h"

namespace simcap {
namespace {

struct Line {
  int number;
  std::vector<std::string> words;
};

// Non-empty lines split into words; '#' starts a comment.
std::vector<Line> lines_of(std::string_view text) {
  std::vector<Line> out;
  int number = 0;
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view raw = text.substr(start, end - start);
    ++number;
    raw = raw.substr(0, raw.find('#'));
    std::istringstream in{std::string(raw)};
    Line line{number, {}};
    for (std::string w; in >> w;) line.words.push_back(w);
    if (!line.words.empty()) out.push_back(std::move(line));
    start = end + 1;
  }
  return out;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

struct Bone {
  std::string name;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double length = 0;
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  std::vector<std::string> dof;  // rx, ry, rz, tx, ty, tz, l (lower case)
  int line = 0;
  int parent = -1;  // bone index; -1: the root
};

class Parser {
 public:
  Parser(const std::filesystem::path& file) : file_(file) {}

  [[noreturn]] void fail(int line, const std::string& message) const {
    throw_input_error(file_, line, "", message);
  }
  double number(const Line& l, size_t i, const std::string& what) const {
    if (i >= l.words.size()) fail(l.number, what + ": expected a number, got the end of the line");
    const std::string& w = l.words[i];
    double v = 0;
    const char* first = w.data() + (w[0] == '+' ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(first, w.data() + w.size(), v);
    if (ec != std::errc() || ptr != w.data() + w.size() || !std::isfinite(v)) {
      fail(l.number, what + ": expected a number, got '" + w + "'");
    }
    return v;
  }
  // Rotation of angles given per axis letter in `order` ("XYZ"): applied first to last about
  // fixed axes, so R = R(order[2]) R(order[1]) R(order[0]).
  Eigen::Matrix3d rotation(const Line& l, size_t first, const std::string& order,
                           double to_radians) const {
    std::string sorted = lower(order);
    std::sort(sorted.begin(), sorted.end());
    if (sorted != "xyz") {
      fail(l.number, "expected an axis order such as XYZ, got '" + order + "'");
    }
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    for (size_t k = 0; k < 3; ++k) {
      const int axis = std::toupper(static_cast<unsigned char>(order[k])) - 'X';
      R = Eigen::AngleAxisd(number(l, first + k, "axis angle") * to_radians,
                            Eigen::Vector3d::Unit(axis))
              .toRotationMatrix() *
          R;
    }
    return R;
  }

 private:
  std::filesystem::path file_;
};

struct Asf {
  std::vector<Bone> bones;
  std::vector<std::string> root_order;  // AMC root value order: tx ty tz rx ry rz (lower case)
  Eigen::Matrix3d root_C = Eigen::Matrix3d::Identity();
  Eigen::Vector3d root_position = Eigen::Vector3d::Zero();
  double length_unit = 1.0;  // :units length
  double to_radians = std::numbers::pi / 180.0;
  int find(const std::string& name) const {
    for (size_t b = 0; b < bones.size(); ++b) {
      if (bones[b].name == name) return static_cast<int>(b);
    }
    return -1;
  }
};

Asf parse_asf(std::string_view text, const std::filesystem::path& file) {
  const Parser p(file);
  const std::vector<Line> lines = lines_of(text);
  Asf asf;
  std::string section;
  bool in_bone = false, in_hierarchy = false, saw_hierarchy = false, saw_root = false;
  Bone bone;
  std::map<std::string, bool> has_parent;
  std::string root_axis = "XYZ";
  int last_line = 1;
  for (const Line& l : lines) {
    last_line = l.number;
    const std::string key = lower(l.words[0]);
    if (key[0] == ':') {
      if (in_bone || in_hierarchy) p.fail(l.number, "expected 'end' before " + l.words[0]);
      section = key;
      if (section == ":units" || section == ":root" || section == ":bonedata" ||
          section == ":hierarchy" || section == ":documentation" || section == ":name" ||
          section == ":version") {
        saw_root |= section == ":root";
        continue;
      }
      p.fail(l.number, "unknown ASF keyword '" + l.words[0] +
                           "' (expected :version, :name, "
                           ":units, :documentation, :root, :bonedata or :hierarchy)");
    }
    if (section == ":units") {
      if (key == "length") asf.length_unit = p.number(l, 1, "units length");
      if (key == "angle") {
        if (l.words.size() < 2 || (lower(l.words[1]) != "deg" && lower(l.words[1]) != "rad")) {
          p.fail(l.number, "units angle: expected deg or rad");
        }
        asf.to_radians = lower(l.words[1]) == "deg" ? std::numbers::pi / 180.0 : 1.0;
      }
    } else if (section == ":root") {
      if (key == "order") {
        for (size_t i = 1; i < l.words.size(); ++i) {
          const std::string d = lower(l.words[i]);
          if (d.size() != 2 || (d[0] != 't' && d[0] != 'r') || d[1] < 'x' || d[1] > 'z') {
            p.fail(l.number,
                   "root order: expected TX, TY, TZ, RX, RY or RZ, got '" + l.words[i] + "'");
          }
          asf.root_order.push_back(d);
        }
      } else if (key == "axis") {
        if (l.words.size() < 2) p.fail(l.number, "root axis: expected an order such as XYZ");
        root_axis = l.words[1];
      } else if (key == "position") {
        asf.root_position = {p.number(l, 1, "root position"), p.number(l, 2, "root position"),
                             p.number(l, 3, "root position")};
      } else if (key == "orientation") {
        asf.root_C = p.rotation(l, 1, root_axis, asf.to_radians);
      } else {
        p.fail(l.number, "unknown :root key '" + l.words[0] +
                             "' (expected order, axis, position or orientation)");
      }
    } else if (section == ":bonedata") {
      if (key == "begin") {
        if (in_bone) p.fail(l.number, "expected 'end' before 'begin'");
        in_bone = true;
        bone = Bone{};
        bone.line = l.number;
      } else if (key == "end") {
        if (!in_bone) p.fail(l.number, "'end' without 'begin'");
        in_bone = false;
        if (bone.name.empty()) p.fail(bone.line, "bone without a name");
        if (asf.find(bone.name) >= 0 || bone.name == "root") {
          p.fail(bone.line, "bone '" + bone.name + "' is defined twice");
        }
        if (!(bone.direction.norm() > 0)) {
          p.fail(bone.line, "bone '" + bone.name + "': expected a non-zero direction");
        }
        bone.direction.normalize();
        asf.bones.push_back(bone);
      } else if (!in_bone) {
        p.fail(l.number, "expected 'begin' of a bone, got '" + l.words[0] + "'");
      } else if (key == "name") {
        if (l.words.size() < 2) p.fail(l.number, "name: expected the bone's name");
        bone.name = l.words[1];
      } else if (key == "direction") {
        bone.direction = {p.number(l, 1, "direction"), p.number(l, 2, "direction"),
                          p.number(l, 3, "direction")};
      } else if (key == "length") {
        bone.length = p.number(l, 1, "length");
      } else if (key == "axis") {
        if (l.words.size() < 5) p.fail(l.number, "axis: expected three angles and an order");
        bone.C = p.rotation(l, 1, l.words[4], asf.to_radians);
      } else if (key == "dof") {
        for (size_t i = 1; i < l.words.size(); ++i) {
          const std::string d = lower(l.words[i]);
          if (d != "rx" && d != "ry" && d != "rz" && d != "tx" && d != "ty" && d != "tz" &&
              d != "l") {
            p.fail(l.number, "dof: expected rx, ry, rz, tx, ty, tz or l, got '" + l.words[i] + "'");
          }
          bone.dof.push_back(d);
        }
      } else if (key == "id" || key == "limits" || key == "bodymass" || key == "cofmass" ||
                 key[0] == '(') {
        // Identifiers, joint limits and masses do not move the skeleton.
      } else {
        p.fail(l.number, "unknown bone key '" + l.words[0] +
                             "' (expected id, name, direction, length, axis, dof or limits)");
      }
    } else if (section == ":hierarchy") {
      if (key == "begin") {
        in_hierarchy = saw_hierarchy = true;
      } else if (key == "end") {
        in_hierarchy = false;
      } else {
        if (!in_hierarchy) p.fail(l.number, "expected 'begin' of the hierarchy");
        const int parent = l.words[0] == "root" ? -1 : asf.find(l.words[0]);
        if (parent < 0 && l.words[0] != "root") {
          p.fail(l.number, "hierarchy: unknown bone '" + l.words[0] + "'");
        }
        for (size_t i = 1; i < l.words.size(); ++i) {
          const int child = asf.find(l.words[i]);
          if (child < 0) p.fail(l.number, "hierarchy: unknown bone '" + l.words[i] + "'");
          if (has_parent[l.words[i]]) {
            p.fail(l.number, "hierarchy: bone '" + l.words[i] + "' has a second parent");
          }
          has_parent[l.words[i]] = true;
          asf.bones[child].parent = parent;
        }
      }
    }
  }
  if (in_bone || in_hierarchy) p.fail(last_line, "unexpected end of the file: expected 'end'");
  if (!saw_root) p.fail(last_line, "no :root section");
  if (!saw_hierarchy) p.fail(last_line, "no :hierarchy section");
  for (const Bone& b : asf.bones) {
    if (!has_parent[b.name]) p.fail(b.line, "bone '" + b.name + "' is not in the :hierarchy");
    // A parent chain that never reaches the root is a cycle.
    int steps = 0;
    for (int k = b.parent; k >= 0; k = asf.bones[k].parent) {
      if (++steps > static_cast<int>(asf.bones.size())) {
        p.fail(b.line, "hierarchy: bone '" + b.name + "' hangs from a cycle");
      }
    }
  }
  if (asf.root_order.empty()) asf.root_order = {"tx", "ty", "tz", "rx", "ry", "rz"};
  return asf;
}

// Rotation from dof values applied in the order listed, about fixed axes.
Eigen::Matrix3d dof_rotation(const std::vector<std::string>& dof, const std::vector<double>& v,
                             double to_radians) {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  for (size_t k = 0; k < dof.size(); ++k) {
    if (dof[k][0] != 'r') continue;
    R = Eigen::AngleAxisd(v[k] * to_radians, Eigen::Vector3d::Unit(dof[k][1] - 'x'))
            .toRotationMatrix() *
        R;
  }
  return R;
}

}  // namespace

BvhClip parse_asf_amc(std::string_view asf_text, const std::filesystem::path& asf_file,
                      std::string_view amc_text, const std::filesystem::path& amc_file,
                      const AsfAmcOptions& options) {
  const Asf asf = parse_asf(asf_text, asf_file);
  if (!(options.fps > 0)) throw Error(amc_file.string() + ": the frame rate must be positive");
  const double unit =
      options.metres_per_unit > 0 ? options.metres_per_unit : 0.0254 / asf.length_unit;

  BvhClip clip;
  clip.file = amc_file;
  clip.frame_time = 1.0 / options.fps;
  clip.metres_per_unit = unit;
  // Joints: root, then bones depth first (parents before children).
  std::vector<int> joint_of_bone(asf.bones.size(), -1);
  BvhJoint root;
  root.name = "root";
  root.channels = {BvhChannel::x_position, BvhChannel::y_position, BvhChannel::z_position,
                   BvhChannel::z_rotation, BvhChannel::y_rotation, BvhChannel::x_rotation};
  clip.joints.push_back(root);
  const auto add_children = [&](auto&& self, int parent_bone, int parent_joint) -> void {
    for (size_t b = 0; b < asf.bones.size(); ++b) {
      if (asf.bones[b].parent != parent_bone) continue;
      BvhJoint j;
      j.name = asf.bones[b].name;
      j.parent = parent_joint;
      j.offset = parent_bone < 0 ? Eigen::Vector3d::Zero()
                                 : Eigen::Vector3d(asf.bones[parent_bone].direction *
                                                   asf.bones[parent_bone].length * unit);
      j.channels = {BvhChannel::z_rotation, BvhChannel::y_rotation, BvhChannel::x_rotation};
      clip.joints.push_back(j);
      const int me = static_cast<int>(clip.joints.size()) - 1;
      joint_of_bone[b] = me;
      const size_t before = clip.joints.size();
      self(self, static_cast<int>(b), me);
      if (clip.joints.size() == before) {
        BvhJoint end;
        end.name = asf.bones[b].name + "_End";
        end.parent = me;
        end.is_end_site = true;
        end.offset = asf.bones[b].direction * asf.bones[b].length * unit;
        clip.joints.push_back(end);
      }
    }
  };
  add_children(add_children, -1, 0);
  int channel = 0;
  for (BvhJoint& j : clip.joints) {
    j.first_channel = channel;
    channel += static_cast<int>(j.channels.size());
  }
  clip.channel_count = channel;

  // AMC: a frame number, then one line per bone with its dof values.
  const Parser p(amc_file);
  const std::vector<Line> lines = lines_of(amc_text);
  std::vector<std::vector<double>> values;  // per bone (root last) of the current frame
  std::vector<bool> seen;
  int frame_number = -1, frame_line = 1, frames = 0;
  const auto finish_frame = [&]() {
    if (frame_number < 0) return;
    std::vector<double> row(clip.channel_count, 0.0);
    // Root: translation (file units) and rotation from its `order`.
    std::vector<double> rv = values.back();
    if (!seen.back())
      p.fail(frame_line, "frame " + std::to_string(frame_number) + ": no root line");
    Eigen::Vector3d t = asf.root_position;
    for (size_t k = 0; k < asf.root_order.size(); ++k) {
      if (asf.root_order[k][0] == 't') t[asf.root_order[k][1] - 'x'] = rv[k];
    }
    const Eigen::Matrix3d Mr = dof_rotation(asf.root_order, rv, asf.to_radians);
    const Eigen::Vector3d root_zyx =
        zyx_degrees(Eigen::Quaterniond(asf.root_C * Mr * asf.root_C.transpose()));
    for (int k = 0; k < 3; ++k) {
      row[k] = t[k] * unit;
      row[3 + k] = root_zyx[k];
    }
    for (size_t b = 0; b < asf.bones.size(); ++b) {
      const Bone& bone = asf.bones[b];
      const bool moves = std::any_of(bone.dof.begin(), bone.dof.end(),
                                     [](const std::string& d) { return d[0] == 'r'; });
      if (!bone.dof.empty() && !seen[b]) {
        p.fail(frame_line, "frame " + std::to_string(frame_number) + ": no values for bone '" +
                               bone.name + "' (its dof: " + std::to_string(bone.dof.size()) +
                               " values)");
      }
      if (!moves) continue;
      const Eigen::Matrix3d M = dof_rotation(bone.dof, values[b], asf.to_radians);
      const Eigen::Vector3d zyx = zyx_degrees(Eigen::Quaterniond(bone.C * M * bone.C.transpose()));
      const int first = clip.joints[joint_of_bone[b]].first_channel;
      for (int k = 0; k < 3; ++k) row[first + k] = zyx[k];
    }
    clip.values.insert(clip.values.end(), row.begin(), row.end());
    ++frames;
  };
  for (const Line& l : lines) {
    const std::string& w = l.words[0];
    if (w[0] == ':') continue;  // :FULLY-SPECIFIED, :DEGREES
    if (l.words.size() == 1 && std::all_of(w.begin(), w.end(), ::isdigit)) {
      finish_frame();
      int n = 0;
      const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), n);
      if (ec != std::errc() || end != w.data() + w.size() || n > limits::kMaxFrames) {
        p.fail(l.number, "expected a frame number up to " + std::to_string(limits::kMaxFrames) +
                             " (simcap's largest frame count), got " + w);
      }
      if (frame_number >= 0 && n != frame_number + 1) {
        p.fail(l.number, "expected frame " + std::to_string(frame_number + 1) + ", got " + w);
      }
      frame_number = n;
      frame_line = l.number;
      values.assign(asf.bones.size() + 1, {});
      seen.assign(asf.bones.size() + 1, false);
      continue;
    }
    if (frame_number < 0) p.fail(l.number, "expected a frame number, got '" + w + "'");
    const int b = w == "root" ? static_cast<int>(asf.bones.size()) : asf.find(w);
    if (b < 0) p.fail(l.number, "unknown bone '" + w + "' (not in " + asf_file.string() + ")");
    if (seen[b])
      p.fail(l.number, "bone '" + w + "' twice in frame " + std::to_string(frame_number));
    const std::vector<std::string>& dof =
        b == static_cast<int>(asf.bones.size()) ? asf.root_order : asf.bones[b].dof;
    if (l.words.size() - 1 != dof.size()) {
      p.fail(l.number, "bone '" + w + "': expected " + std::to_string(dof.size()) +
                           " values (its dof), got " + std::to_string(l.words.size() - 1));
    }
    for (size_t k = 0; k < dof.size(); ++k) values[b].push_back(p.number(l, k + 1, w));
    seen[b] = true;
  }
  finish_frame();
  if (frames == 0) p.fail(lines.empty() ? 1 : lines.back().number, "expected at least 1 frame");
  return clip;
}

BvhClip read_asf_amc(const std::filesystem::path& asf, const std::filesystem::path& amc,
                     const AsfAmcOptions& options) {
  return parse_asf_amc(read_text(asf), asf, read_text(amc), amc, options);
}

}  // namespace simcap
