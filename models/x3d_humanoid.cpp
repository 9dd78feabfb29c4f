#include "models/x3d_humanoid.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <map>
#include <pugixml.hpp>
#include <set>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {
namespace {

// HAnimSite names that become simcap's end sites.
const std::map<std::string, std::string>& site_names() {
  static const std::map<std::string, std::string> names = [] {
    std::map<std::string, std::string> m;
    for (const char* n : {"skull_tip", "l_hand_tip", "r_hand_tip", "l_toe_tip", "r_toe_tip"}) {
      m[n] = n;
    }
    for (const char* suffix : {"", "_pt"}) {
      const std::string s(suffix);
      m["skull_vertex" + s] = "skull_tip";
      m["l_dactylion" + s] = "l_hand_tip";
      m["r_dactylion" + s] = "r_hand_tip";
    }
    return m;
  }();
  return names;
}

class Reader {
 public:
  Reader(std::string_view text, const std::filesystem::path& file) : text_(text), file_(file) {}

  SkinnedSkeleton read(std::vector<std::string>& notes) {
    load();
    std::vector<pugi::xml_node> humanoids;
    for (const pugi::xpath_node& x : doc_.select_nodes("//HAnimHumanoid[not(@USE)]")) {
      humanoids.push_back(x.node());
    }
    if (humanoids.empty()) fail(1, "expected an HAnimHumanoid, found none");
    if (humanoids.size() > 1) {
      fail(line(humanoids[1]), "expected one HAnimHumanoid, found " +
                                   std::to_string(humanoids.size()) + " (a second one here)");
    }
    const pugi::xml_node humanoid = humanoids[0];
    require_identity(humanoid, "HAnimHumanoid");
    for (const pugi::xpath_node& x : humanoid.select_nodes("descendant::*[@USE]")) {
      resolve(x.node(), x.node().name());
    }

    SkinnedSkeleton out;
    read_joints(humanoid, out, notes);
    read_skin(humanoid, out, notes);
    return out;
  }

  Motion read_motion(const Skeleton& skeleton) {
    load();
    const pugi::xpath_node found = doc_.select_node("//HAnimMotion[not(@USE)]");
    if (!found) fail(1, "expected an HAnimMotion, found none");
    const pugi::xml_node m = found.node();
    std::vector<int> joints;
    {
      std::istringstream in(m.attribute("joints").value());
      for (std::string name; in >> name;) {
        if (name == "HumanoidRoot") name = "humanoid_root";
        const int j = name == "IGNORED" ? -1 : skeleton.find(name);
        if (j < 0 && name != "IGNORED") {
          fail(line(m), "HAnimMotion joints: '" + name + "' is not a joint of the humanoid");
        }
        joints.push_back(j);
      }
    }
    std::vector<std::vector<std::string>> channels;
    {
      std::istringstream in(m.attribute("channels").value());
      for (std::string word; in >> word;) {
        int count = 0;
        const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), count);
        if (ec != std::errc() || ptr != word.data() + word.size() || count < 0 || count > 9) {
          fail(line(m), "HAnimMotion channels: expected a channel count, got '" + word + "'");
        }
        auto& list = channels.emplace_back();
        for (int k = 0; k < count && in >> word; ++k) {
          static const std::set<std::string> known = {"Xposition", "Yposition", "Zposition",
                                                      "Xrotation", "Yrotation", "Zrotation"};
          if (!known.count(word)) {
            fail(line(m),
                 "HAnimMotion channels: expected Xposition, Yposition, Zposition, "
                 "Xrotation, Yrotation or Zrotation, got '" +
                     word + "'");
          }
          list.push_back(word);
        }
        if (static_cast<int>(list.size()) != count) {
          fail(line(m), "HAnimMotion channels: expected " + std::to_string(count) +
                            " channel names, got " + std::to_string(list.size()));
        }
      }
    }
    if (channels.size() != joints.size()) {
      fail(line(m), "HAnimMotion: expected channels for the " + std::to_string(joints.size()) +
                        " joints, got " + std::to_string(channels.size()));
    }
    size_t per_frame = 0;
    for (const auto& c : channels) per_frame += c.size();
    const std::vector<double> values = numbers(m, "values");
    if (per_frame == 0 || values.empty() || values.size() % per_frame != 0) {
      fail(line(m), "HAnimMotion values: expected a whole number of frames of " +
                        std::to_string(per_frame) + " values, got " +
                        std::to_string(values.size()));
    }
    const std::vector<double> duration = numbers(m, "frameDuration");
    const double frame_time = duration.empty() ? 0.1 : duration[0];  // X3D's default
    if (!(frame_time > 0)) fail(line(m), "HAnimMotion frameDuration: expected seconds > 0");
    Motion motion;
    motion.fps = 1.0 / frame_time;
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    for (size_t v = 0; v < values.size();) {
      Pose pose = Pose::neutral(skeleton);
      for (size_t k = 0; k < joints.size(); ++k) {
        Eigen::Vector3d t = Eigen::Vector3d::Zero();
        Eigen::Quaterniond r = Eigen::Quaterniond::Identity();
        for (const std::string& c : channels[k]) {
          const double x = values[v++];
          const int axis = c[0] - 'X';
          if (c.ends_with("position")) {
            t[axis] = x;
          } else {
            r = r * Eigen::AngleAxisd(x * kDeg, Eigen::Vector3d::Unit(axis));
          }
        }
        const int j = joints[k];
        if (j < 0) continue;
        pose.rotations[j] = r;
        if (j == 0) pose.root_position = skeleton[0].center + t;
      }
      motion.frames.push_back(std::move(pose));
    }
    return motion;
  }

 private:
  void load() {
    const pugi::xml_parse_result parsed =
        doc_.load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
    if (!parsed) {
      fail(line_at(parsed.offset), std::string("not well-formed XML: ") + parsed.description());
    }
    index_defs(doc_.document_element());
  }

  int line_at(std::ptrdiff_t offset) const {
    const size_t end = std::min<size_t>(std::max<std::ptrdiff_t>(offset, 0), text_.size());
    return 1 + static_cast<int>(std::count(text_.begin(), text_.begin() + end, '\n'));
  }
  int line(const pugi::xml_node& node) const { return line_at(node.offset_debug()); }
  [[noreturn]] void fail(int line, const std::string& message) const {
    throw_input_error(file_, line, "", message);
  }
  // "HAnimJoint 'l_knee'" or "HAnimJoint" when it has no name.
  static std::string describe(const pugi::xml_node& node) {
    const char* name = node.attribute("name").value();
    return std::string(node.name()) + (*name ? " '" + std::string(name) + "'" : "");
  }

  void index_defs(const pugi::xml_node& root) {
    for (const pugi::xpath_node& x : root.select_nodes("descendant-or-self::*[@DEF]")) {
      const pugi::xml_node n = x.node();
      const std::string def = n.attribute("DEF").value();
      if (!defs_.emplace(def, n).second) {
        fail(line(n), "DEF '" + def + "' is defined twice (first on line " +
                          std::to_string(line(defs_.at(def))) + ")");
      }
    }
  }

  // The node a USE names, or the node itself; it must be a `tag` element.
  pugi::xml_node resolve(const pugi::xml_node& node, const char* tag) const {
    pugi::xml_node target = node;
    if (const pugi::xml_attribute use = node.attribute("USE")) {
      const auto it = defs_.find(use.value());
      if (it == defs_.end()) {
        fail(line(node), std::string(node.name()) + " USE='" + use.value() +
                             "': expected the DEF name of a node, found none");
      }
      target = it->second;
    }
    if (std::strcmp(target.name(), tag) != 0) {
      fail(line(node), std::string("expected a ") + tag + ", got " + target.name());
    }
    return target;
  }

  // Numbers of an X3D multi-value field (separated by white space or commas).
  std::vector<double> numbers(const pugi::xml_node& node, const char* field) const {
    std::vector<double> out;
    const std::string_view text = node.attribute(field).value();
    size_t i = 0;
    auto separator = [](char c) { return c == ',' || std::isspace(static_cast<unsigned char>(c)); };
    while (i < text.size()) {
      if (separator(text[i])) {
        ++i;
        continue;
      }
      size_t end = i;
      while (end < text.size() && !separator(text[end])) ++end;
      double v = 0;
      const char* first = text.data() + i;
      const char* last = text.data() + end;
      if (*first == '+') ++first;
      const auto [ptr, ec] = std::from_chars(first, last, v);
      if (ec != std::errc() || ptr != last || !std::isfinite(v)) {
        fail(line(node), describe(node) + ": " + field + ": expected a number, got '" +
                             std::string(text.substr(i, end - i)) + "'");
      }
      out.push_back(v);
      i = end;
    }
    return out;
  }
  std::vector<int> integers(const pugi::xml_node& node, const char* field) const {
    std::vector<int> out;
    for (const double v : numbers(node, field)) {
      if (v != std::floor(v) || std::abs(v) > 2e9) {
        fail(line(node),
             describe(node) + ": " + field + ": expected integers, got " + std::to_string(v));
      }
      out.push_back(static_cast<int>(v));
    }
    return out;
  }
  Eigen::Vector3d vec3(const pugi::xml_node& node, const char* field) const {
    if (!node.attribute(field)) return Eigen::Vector3d::Zero();
    const auto v = numbers(node, field);
    if (v.size() != 3) {
      fail(line(node),
           describe(node) + ": " + field + ": expected 3 numbers, got " + std::to_string(v.size()));
    }
    return {v[0], v[1], v[2]};
  }

  // simcap reads a humanoid in its default pose: no transform on the humanoid or its joints.
  void require_identity(const pugi::xml_node& node, const std::string& what) const {
    const auto check = [&](const char* field, std::vector<double> identity) {
      if (!node.attribute(field)) return;
      const auto v = numbers(node, field);
      bool same = v.size() == identity.size();
      for (size_t k = 0; same && k < v.size(); ++k) same = std::abs(v[k] - identity[k]) < 1e-9;
      // A rotation of angle 0 about any axis is the identity too.
      if (!same && identity.size() == 4 && v.size() == 4) same = std::abs(v[3]) < 1e-9;
      if (!same) {
        fail(line(node), what + " " + describe(node) + ": " + field +
                             ": simcap reads humanoids in their default pose; expected " +
                             (identity.size() == 4 ? "0 0 1 0"
                              : identity[0] == 1   ? "1 1 1"
                                                   : "0 0 0") +
                             ", got '" + node.attribute(field).value() + "'");
      }
    };
    check("translation", {0, 0, 0});
    check("rotation", {0, 0, 1, 0});
    check("scale", {1, 1, 1});
  }

  void read_joints(const pugi::xml_node& humanoid, SkinnedSkeleton& out,
                   std::vector<std::string>& notes) {
    std::vector<pugi::xml_node> roots;
    for (const pugi::xpath_node& x :
         humanoid.select_nodes("descendant::HAnimJoint[not(@USE) and not(ancestor::HAnimJoint)]")) {
      roots.push_back(x.node());
    }
    if (roots.empty()) fail(line(humanoid), "the HAnimHumanoid has no HAnimJoint");
    if (roots.size() > 1) {
      fail(line(roots[1]),
           "expected one root HAnimJoint (humanoid_root), found a second: " + describe(roots[1]));
    }
    add_joint(roots[0], -1, out);
    if (!ignored_sites_.empty()) {
      notes.push_back("HAnimSites without a simcap end site were left out: " + ignored_sites_);
    }
  }

  void add_joint(const pugi::xml_node& node, int parent, SkinnedSkeleton& out) {
    std::string name = node.attribute("name").value();
    if (name.empty()) fail(line(node), "HAnimJoint: expected a name attribute (an H-Anim name)");
    if (name == "HumanoidRoot") name = "humanoid_root";  // H-Anim 1.1
    if (out.skeleton.find(name) >= 0) {
      fail(line(node), "HAnimJoint '" + name + "': the name is used by another joint");
    }
    require_identity(node, "HAnimJoint");
    const int j = out.skeleton.add({name, "", parent, vec3(node, "center"), false});
    joint_nodes_.push_back(node);
    for (const pugi::xml_node& child : node.children()) {
      if (std::strcmp(child.name(), "HAnimJoint") == 0) {
        if (child.attribute("USE")) {
          fail(line(child), "HAnimJoint USE='" + std::string(child.attribute("USE").value()) +
                                "' inside a joint: expected each joint once in the tree");
        }
        add_joint(child, j, out);
      } else if (std::strcmp(child.name(), "HAnimSite") == 0) {
        const pugi::xml_node site = resolve(child, "HAnimSite");
        const std::string site_name = site.attribute("name").value();
        const auto it = site_names().find(site_name);
        if (it == site_names().end()) {
          ignored_sites_ += (ignored_sites_.empty() ? "" : ", ") + site_name;
        } else if (out.skeleton.find(it->second) < 0 &&
                   std::none_of(site_nodes_.begin(), site_nodes_.end(),
                                [&](const PendingSite& s) { return s.name == it->second; })) {
          site_nodes_.push_back({it->second, j, vec3(site, "translation")});
        }
      }
    }
    if (parent < 0) {
      for (const auto& s : site_nodes_) out.skeleton.add({s.name, "", s.parent, s.position, true});
    }
  }

  void read_skin(const pugi::xml_node& humanoid, SkinnedSkeleton& out,
                 std::vector<std::string>& notes) {
    pugi::xml_node coord;
    for (const pugi::xml_node& child : humanoid.children("Coordinate")) {
      if (std::strcmp(child.attribute("containerField").value(), "skinCoord") == 0) {
        coord = resolve(child, "Coordinate");
      }
    }
    if (!coord) {
      fail(line(humanoid),
           "HAnimHumanoid: expected a Coordinate with containerField='skinCoord' (the skin's "
           "points), found none");
    }
    const std::vector<double> p = numbers(coord, "point");
    if (p.size() % 3 != 0) {
      fail(line(coord), "Coordinate point: expected x y z triples, got " +
                            std::to_string(p.size()) + " numbers");
    }
    const int point_count = static_cast<int>(p.size() / 3);
    for (int v = 0; v < point_count; ++v) {
      out.vertices.emplace_back(static_cast<float>(p[3 * v]), static_cast<float>(p[3 * v + 1]),
                                static_cast<float>(p[3 * v + 2]));
    }

    int shapes = 0;
    for (const pugi::xml_node& child : humanoid.children()) {
      if (std::strcmp(child.attribute("containerField").value(), "skin") != 0) continue;
      for (const pugi::xpath_node& x : child.select_nodes("descendant-or-self::Shape")) {
        read_shape(resolve(x.node(), "Shape"), coord, point_count, out);
        ++shapes;
      }
    }
    if (shapes == 0) {
      fail(line(humanoid),
           "HAnimHumanoid: expected a Shape with containerField='skin' (the skin), found none");
    }

    out.weights.assign(point_count, {});
    for (size_t j = 0; j < joint_nodes_.size(); ++j) {
      const pugi::xml_node& node = joint_nodes_[j];
      const std::vector<int> index = integers(node, "skinCoordIndex");
      const std::vector<double> weight = numbers(node, "skinCoordWeight");
      if (weight.size() < index.size()) {
        fail(line(node),
             describe(node) + ": skinCoordWeight: expected " + std::to_string(index.size()) +
                 " weights (one per skinCoordIndex), got " + std::to_string(weight.size()));
      }
      if (weight.size() > index.size()) {
        notes.push_back(file_.filename().string() + ":" + std::to_string(line(node)) + ": " +
                        describe(node) + " has " + std::to_string(weight.size()) +
                        " skinCoordWeight values for " + std::to_string(index.size()) +
                        " skinCoordIndex values; the extra weights were ignored");
      }
      for (size_t k = 0; k < index.size(); ++k) {
        if (index[k] < 0 || index[k] >= point_count) {
          fail(line(node), describe(node) + ": skinCoordIndex: expected indices in [0, " +
                               std::to_string(point_count) + "), got " + std::to_string(index[k]));
        }
        if (weight[k] < 0 || weight[k] > 1) {
          fail(line(node), describe(node) + ": skinCoordWeight: expected weights in [0, 1], got " +
                               std::to_string(weight[k]));
        }
        out.weights[index[k]].emplace_back(static_cast<int>(j), static_cast<float>(weight[k]));
      }
    }
  }

  void read_shape(const pugi::xml_node& shape, const pugi::xml_node& coord, int point_count,
                  SkinnedSkeleton& out) const {
    const pugi::xml_node faces_node = shape.child("IndexedFaceSet");
    if (!faces_node) {
      fail(line(shape), "skin Shape: expected an IndexedFaceSet geometry (simcap reads no other)");
    }
    const pugi::xml_node faces = resolve(faces_node, "IndexedFaceSet");
    const pugi::xml_node own = faces.child("Coordinate");
    if (!own || resolve(own, "Coordinate") != coord) {
      fail(line(faces),
           "skin IndexedFaceSet: expected its Coordinate to be the humanoid's skinCoord (USE it)");
    }
    const bool ccw = std::strcmp(faces.attribute("ccw").value(), "false") != 0;
    std::vector<int> polygon;
    auto flush = [&] {
      if (polygon.empty()) return;
      if (polygon.size() < 3) {
        fail(line(faces),
             "IndexedFaceSet coordIndex: expected polygons of 3 or more corners, got " +
                 std::to_string(polygon.size()));
      }
      for (size_t k = 1; k + 1 < polygon.size(); ++k) {
        std::array<std::uint32_t, 3> t = {static_cast<std::uint32_t>(polygon[0]),
                                          static_cast<std::uint32_t>(polygon[k]),
                                          static_cast<std::uint32_t>(polygon[k + 1])};
        if (!ccw) std::swap(t[1], t[2]);
        out.triangles.push_back(t);
      }
      polygon.clear();
    };
    for (const int i : integers(faces, "coordIndex")) {
      if (i == -1) {
        flush();
        continue;
      }
      if (i < 0 || i >= point_count) {
        fail(line(faces), "IndexedFaceSet coordIndex: expected -1 or an index in [0, " +
                              std::to_string(point_count) + "), got " + std::to_string(i));
      }
      polygon.push_back(i);
    }
    flush();
  }

  struct PendingSite {
    std::string name;
    int parent;
    Eigen::Vector3d position;
  };

  std::string_view text_;
  std::filesystem::path file_;
  pugi::xml_document doc_;
  std::map<std::string, pugi::xml_node> defs_;
  std::vector<pugi::xml_node> joint_nodes_;  // per skeleton joint (sites come after)
  std::vector<PendingSite> site_nodes_;
  std::string ignored_sites_;
};

}  // namespace

Body parse_x3d_humanoid(std::string_view text, const std::filesystem::path& file) {
  std::vector<std::string> notes;
  SkinnedSkeleton found = Reader(text, file).read(notes);
  Body body = finish_imported_body(std::move(found), file);
  body.notes.insert(body.notes.begin(), notes.begin(), notes.end());
  return body;
}

Body read_x3d_humanoid(const std::filesystem::path& path) {
  return parse_x3d_humanoid(read_text(path), path);
}

Motion parse_x3d_motion(std::string_view text, const std::filesystem::path& file,
                        const Skeleton& skeleton) {
  return Reader(text, file).read_motion(skeleton);
}

Motion read_x3d_motion(const std::filesystem::path& path, const Skeleton& skeleton) {
  return parse_x3d_motion(read_text(path), path, skeleton);
}

}  // namespace simcap
