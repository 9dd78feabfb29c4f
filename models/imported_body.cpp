#include "models/imported_body.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"
#include "models/humanoid.h"

namespace simcap {
namespace {

bool starts_with(std::string_view s, std::string_view prefix) {
  return s.substr(0, prefix.size()) == prefix;
}

// "<side>_<stem>_<digit>" -> its parts; nullopt for other names.
struct SidedName {
  std::string side;  // "l_" or "r_"
  std::string stem;
  std::string digit;  // "" when the name has none
};
std::optional<SidedName> split_sided(std::string_view joint) {
  if (!starts_with(joint, "l_") && !starts_with(joint, "r_")) return std::nullopt;
  SidedName n{std::string(joint.substr(0, 2)), std::string(joint.substr(2)), ""};
  const size_t underscore = n.stem.rfind('_');
  if (underscore != std::string::npos && underscore + 2 == n.stem.size() &&
      std::isdigit(static_cast<unsigned char>(n.stem.back()))) {
    n.digit = n.stem.substr(underscore + 1);
    n.stem.resize(underscore);
  }
  return n;
}

MaterialRegion region_of_joint(const Skeleton& s, int j) {
  for (int k = j; k >= 0; k = s[k].parent) {
    const std::string& n = s[k].name;
    if (n == "l_talocrural" || n == "r_talocrural") return MaterialRegion::shoes;
    if (n == "l_radiocarpal" || n == "r_radiocarpal" || n == "skullbase" || starts_with(n, "vc"))
      return MaterialRegion::skin;
    if (n == "l_hip" || n == "r_hip" || n == "sacroiliac" || n == "humanoid_root")
      return MaterialRegion::trousers;
    if (starts_with(n, "vl") || starts_with(n, "vt") || n == "l_shoulder" || n == "r_shoulder" ||
        n == "l_sternoclavicular" || n == "r_sternoclavicular")
      return MaterialRegion::shirt;
  }
  return MaterialRegion::shirt;
}

double distance_to_segment(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                           const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// The joint whose bone (its centre to a child's centre) passes nearest to `p`.
int nearest_bone(const Skeleton& s, const Eigen::Vector3d& p) {
  int best = 0;
  double best_d = INFINITY;
  for (int j = 1; j < s.size(); ++j) {
    const int parent = s[j].parent;
    const double d = distance_to_segment(p, s[parent].center, s[j].center);
    if (d < best_d) {
      best_d = d;
      best = parent;
    }
  }
  return best;
}

// Adds the end site `name` under `parent` at the skin vertex that maximizes `score` among the
// vertices whose part lies below `region_root`; a note when there is no such vertex.
template <class Score>
void add_site(Skeleton& s, const BodyMesh& mesh, const std::string& name, int parent,
              int region_root, Score score, std::vector<std::string>& notes) {
  if (s.find(name) >= 0) return;
  std::optional<Eigen::Vector3d> best;
  double best_score = -INFINITY;
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (!s.is_descendant(mesh.vertex_segment[v], region_root)) continue;
    const Eigen::Vector3d p = mesh.vertices[v].cast<double>();
    const double value = score(p);
    if (value > best_score) {
      best_score = value;
      best = p;
    }
  }
  if (!best) {
    notes.push_back("no end site " + name + ": no skin below " + s[region_root].name);
    return;
  }
  s.add({name, "", parent, *best, true});
}

}  // namespace

const std::vector<std::string>& required_body_joints() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n = {"humanoid_root", "vc7", "skullbase"};
    for (const char* side : {"l_", "r_"}) {
      for (const char* joint : {"hip", "knee", "talocrural", "metatarsophalangeal_2", "shoulder",
                                "elbow", "radiocarpal"}) {
        n.push_back(std::string(side) + joint);
      }
    }
    return n;
  }();
  return names;
}

std::string hanim_segment_of(std::string_view joint) {
  static const Skeleton canonical = build_humanoid();
  const int c = canonical.find(joint);
  if (c >= 0 && !canonical[c].is_site) return canonical[c].segment;
  if (joint.size() >= 3 &&
      (starts_with(joint, "vl") || starts_with(joint, "vt") || starts_with(joint, "vc"))) {
    return std::string(joint.substr(1));  // vt12 -> t12
  }
  if (const auto n = split_sided(joint)) {
    const std::string& d = n->digit;
    // H-Anim 2.0 (ISO/IEC 19774-1, the joint and segment tables): each joint moves the segment
    // distal to it.
    const std::pair<const char*, std::string> table[] = {
        {"eyeball_joint", "eyeball"},
        {"acromioclavicular", "scapula"},
        {"midcarpal", "trapezium"},
        {"carpometacarpal", "metacarpal_" + d},
        {"metacarpophalangeal", "carpal_proximal_phalanx_" + d},
        {"carpal_interphalangeal", "carpal_distal_phalanx_" + d},
        {"carpal_proximal_interphalangeal", "carpal_middle_phalanx_" + d},
        {"carpal_distal_interphalangeal", "carpal_distal_phalanx_" + d},
        {"subtalar", "calcaneus"},
        {"talocalcaneonavicular", "navicular"},
        {"calcaneocuboid", "cuboid"},
        {"cuneonavicular", "cuneiform_" + d},
        {"tarsometatarsal", "metatarsal_" + d},
        {"metatarsophalangeal", "tarsal_proximal_phalanx_" + d},
        {"tarsal_interphalangeal", "tarsal_distal_phalanx_" + d},
        {"tarsal_proximal_interphalangeal", "tarsal_middle_phalanx_" + d},
        {"tarsal_distal_interphalangeal", "tarsal_distal_phalanx_" + d},
    };
    for (const auto& [stem, segment] : table) {
      if (n->stem == stem) return n->side + segment;
    }
  }
  if (joint == "temporomandibular") return "jaw";
  return std::string(joint);
}

Body finish_imported_body(SkinnedSkeleton found, const std::filesystem::path& file) {
  const std::string where = file.string() + ": ";
  Body out;
  Skeleton& s = found.skeleton;
  std::string missing;
  for (const std::string& name : required_body_joints()) {
    if (s.find(name) < 0) missing += (missing.empty() ? "" : ", ") + name;
  }
  if (!missing.empty()) {
    throw Error(where + "the humanoid lacks H-Anim joints simcap needs: " + missing);
  }
  if (s[0].name != "humanoid_root") {
    throw Error(where + "the skeleton's root must be humanoid_root, got '" + s[0].name + "'");
  }
  if (s.size() > 255) {
    throw Error(where + "the skeleton has " + std::to_string(s.size()) +
                " joints; simcap's 8-bit part labels allow at most 255");
  }
  const size_t n = found.vertices.size();
  if (found.weights.size() != n) {
    throw Error(where + std::to_string(n) + " vertices but " +
                std::to_string(found.weights.size()) + " weight lists");
  }
  if (found.triangles.empty()) throw Error(where + "the skin has no triangles");
  {
    float low = INFINITY, high = -INFINITY;
    for (const auto& v : found.vertices) {
      low = std::min(low, v.y());
      high = std::max(high, v.y());
    }
    // A body in centimetres or lying on its back is caught here, before anything renders.
    if (!(high - low >= 0.3f && high - low <= 3.0f)) {
      throw Error(where + "expected a standing body 0.3 to 3 m tall (metres, +Y up), got a skin " +
                  std::to_string(high - low) + " units tall");
    }
  }

  // Keep the vertices the triangles use, in their order of first use.
  std::vector<std::uint32_t> new_index(n, ~0u);
  std::vector<std::uint32_t> kept;
  for (auto& t : found.triangles) {
    for (std::uint32_t& v : t) {
      if (v >= n) {
        throw Error(where + "a triangle uses vertex " + std::to_string(v) + " of " +
                    std::to_string(n));
      }
      if (new_index[v] == ~0u) {
        new_index[v] = static_cast<std::uint32_t>(kept.size());
        kept.push_back(v);
      }
      v = new_index[v];
    }
  }
  if (kept.size() < n) {
    out.notes.push_back(std::to_string(n - kept.size()) +
                        " skin vertices no triangle uses were dropped");
  }

  Skeleton skeleton;
  for (const Joint& j : s.joints()) {
    Joint copy = j;
    if (!copy.is_site && copy.segment.empty()) copy.segment = hanim_segment_of(copy.name);
    skeleton.add(std::move(copy));
  }

  BodyMesh& mesh = out.mesh;
  int unweighted = 0;
  for (const std::uint32_t v : kept) {
    const Eigen::Vector3f p = found.vertices[v];
    std::vector<std::pair<int, float>> w;
    for (const auto& [joint, weight] : found.weights[v]) {
      if (!(weight > 0)) continue;
      if (joint < 0 || joint >= skeleton.size() || skeleton[joint].is_site) {
        throw Error(where + "vertex " + std::to_string(v) + " is weighted to joint " +
                    std::to_string(joint) + ", which is not a joint of the skeleton");
      }
      w.emplace_back(joint, weight);
    }
    if (w.empty()) {
      ++unweighted;
      w.emplace_back(nearest_bone(skeleton, p.cast<double>()), 1.0f);
    }
    // Largest weights first, lower joint index first among equals (deterministic).
    std::sort(w.begin(), w.end(), [](const auto& a, const auto& b) {
      return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    if (w.size() > 4) w.resize(4);
    float sum = 0;
    for (const auto& e : w) sum += e.second;
    std::array<std::uint16_t, 4> joints{};
    std::array<float, 4> weights{};
    for (size_t k = 0; k < w.size(); ++k) {
      joints[k] = static_cast<std::uint16_t>(w[k].first);
      weights[k] = w[k].second / sum;
    }
    for (size_t k = w.size(); k < 4; ++k) joints[k] = joints[0];
    if (w.size() == 1) weights[0] = 1.0f;
    mesh.vertices.push_back(p);
    mesh.influence_joint.push_back(joints);
    mesh.influence_weight.push_back(weights);
    mesh.vertex_segment.push_back(joints[0]);
  }
  if (unweighted) {
    out.notes.push_back(std::to_string(unweighted) +
                        " skin vertices without weights follow the nearest bone");
  }
  mesh.triangles = std::move(found.triangles);

  std::vector<MaterialRegion> joint_region(skeleton.size());
  for (int j = 0; j < skeleton.size(); ++j) joint_region[j] = region_of_joint(skeleton, j);
  for (const auto& t : mesh.triangles) {
    const MaterialRegion a = joint_region[mesh.vertex_segment[t[0]]];
    const MaterialRegion b = joint_region[mesh.vertex_segment[t[1]]];
    const MaterialRegion c = joint_region[mesh.vertex_segment[t[2]]];
    mesh.triangle_material.push_back(b == c ? b : a);
  }

  const int skull = skeleton.require("skullbase");
  add_site(
      skeleton, mesh, "skull_tip", skull, skull, [](const Eigen::Vector3d& p) { return p.y(); },
      out.notes);
  for (const char* side : {"l_", "r_"}) {
    const std::string p(side);
    const int wrist = skeleton.require(p + "radiocarpal");
    const Eigen::Vector3d wrist_centre = skeleton[wrist].center;
    add_site(
        skeleton, mesh, p + "hand_tip", wrist, wrist,
        [&](const Eigen::Vector3d& x) { return (x - wrist_centre).norm(); }, out.notes);
    int toe_parent = skeleton.require(p + "metatarsophalangeal_2");
    for (auto kids = skeleton.children(toe_parent); !kids.empty();
         kids = skeleton.children(toe_parent)) {
      toe_parent = kids[0];
    }
    add_site(
        skeleton, mesh, p + "toe_tip", toe_parent, skeleton.require(p + "talocrural"),
        [](const Eigen::Vector3d& x) { return x.z(); }, out.notes);
  }
  out.skeleton = std::move(skeleton);
  return out;
}

}  // namespace simcap
