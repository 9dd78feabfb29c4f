#include "models/x3d_export.h"

#include <pugixml.hpp>
#include <sstream>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/literal_text.h"
#include "models/bvh_export.h"

namespace simcap {
namespace {

template <class Vector>
std::string triple(const Vector& v) {
  return shortest_text(v.x()) + " " + shortest_text(v.y()) + " " + shortest_text(v.z());
}

class Writer {
 public:
  Writer(const Skeleton& s, const BodyMesh& m) : s_(s), index_(s.size()), weight_(s.size()) {
    for (size_t v = 0; v < m.vertices.size(); ++v) {
      for (int k = 0; k < 4; ++k) {
        if (m.influence_weight[v][k] <= 0) continue;
        index_[m.influence_joint[v][k]] +=
            (index_[m.influence_joint[v][k]].empty() ? "" : " ") + std::to_string(v);
        weight_[m.influence_joint[v][k]] += (weight_[m.influence_joint[v][k]].empty() ? "" : " ") +
                                            shortest_text(m.influence_weight[v][k]);
      }
    }
  }

  void joint(pugi::xml_node parent, int j, bool root) const {
    pugi::xml_node n = parent.append_child(s_[j].is_site ? "HAnimSite" : "HAnimJoint");
    n.append_attribute("DEF") = ((s_[j].is_site ? "S_" : "J_") + s_[j].name).c_str();
    n.append_attribute("name") = s_[j].name.c_str();
    if (s_[j].is_site) {
      n.append_attribute("translation") = triple(s_[j].center).c_str();
      return;
    }
    if (root) n.append_attribute("containerField") = "skeleton";
    n.append_attribute("center") = triple(s_[j].center).c_str();
    if (!index_[j].empty()) {
      n.append_attribute("skinCoordIndex") = index_[j].c_str();
      n.append_attribute("skinCoordWeight") = weight_[j].c_str();
    }
    for (const int k : s_.children(j)) joint(n, k, false);
  }

 private:
  const Skeleton& s_;
  std::vector<std::string> index_, weight_;  // per joint: skinCoordIndex, skinCoordWeight
};

void add_motion(pugi::xml_node humanoid, const Skeleton& s, const Motion& motion) {
  if (motion.frames.empty() || !(motion.fps > 0)) {
    throw Error("X3D export: the motion has no frames or no frame rate");
  }
  std::string joints, channels, values;
  for (int j = 0; j < s.size(); ++j) {
    if (s[j].is_site) continue;
    joints += (joints.empty() ? "" : " ") + s[j].name;
    channels += std::string(channels.empty() ? "" : " ") +
                (j == 0 ? "6 Xposition Yposition Zposition " : "3 ") +
                "Zrotation Yrotation Xrotation";
  }
  for (const Pose& pose : motion.frames) {
    if (static_cast<int>(pose.rotations.size()) != s.size()) {
      throw Error("X3D export: a pose is not of the skeleton");
    }
    for (int j = 0; j < s.size(); ++j) {
      if (s[j].is_site) continue;
      if (j == 0) values += (values.empty() ? "" : " ") + triple(pose.root_position - s[0].center);
      values += " " + triple(zyx_degrees(pose.rotations[j]));
    }
  }
  pugi::xml_node m = humanoid.append_child("HAnimMotion");
  m.append_attribute("DEF") = "motion";
  m.append_attribute("containerField") = "motions";
  m.append_attribute("name") = "motion";
  m.append_attribute("loop") = "true";
  m.append_attribute("frameDuration") = shortest_text(1.0 / motion.fps).c_str();
  m.append_attribute("joints") = joints.c_str();
  m.append_attribute("channels") = channels.c_str();
  m.append_attribute("values") = values.c_str();
}

}  // namespace

std::string format_x3d_humanoid(const std::string& name, const Skeleton& skeleton,
                                const BodyMesh& mesh,
                                const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors,
                                const Motion* motion) {
  if (skeleton.size() == 0) throw Error("X3D export: the skeleton is empty");
  pugi::xml_document doc;
  auto decl = doc.append_child(pugi::node_declaration);
  decl.append_attribute("version") = "1.0";
  decl.append_attribute("encoding") = "UTF-8";
  pugi::xml_node x3d = doc.append_child("X3D");
  x3d.append_attribute("profile") = "Immersive";
  x3d.append_attribute("version") = "4.0";
  pugi::xml_node head = x3d.append_child("head");
  auto component = head.append_child("component");
  component.append_attribute("name") = "HAnim";
  component.append_attribute("level") = motion ? "3" : "1";
  auto meta = head.append_child("meta");
  meta.append_attribute("name") = "generator";
  meta.append_attribute("content") = "simcap";
  pugi::xml_node humanoid = x3d.append_child("Scene").append_child("HAnimHumanoid");
  humanoid.append_attribute("DEF") = "humanoid";
  humanoid.append_attribute("name") = name.c_str();
  humanoid.append_attribute("version") = "2.0";

  Writer(skeleton, mesh).joint(humanoid, 0, true);
  for (int j = 0; j < skeleton.size(); ++j) {
    if (skeleton[j].is_site) continue;
    pugi::xml_node use = humanoid.append_child("HAnimJoint");
    use.append_attribute("USE") = ("J_" + skeleton[j].name).c_str();
    use.append_attribute("containerField") = "joints";
  }
  std::string points;
  for (const auto& v : mesh.vertices) points += (points.empty() ? "" : " ") + triple(v);
  pugi::xml_node coord = humanoid.append_child("Coordinate");
  coord.append_attribute("DEF") = "skin_points";
  coord.append_attribute("containerField") = "skinCoord";
  coord.append_attribute("point") = points.c_str();
  for (int r = 0; r < kMaterialRegionCount; ++r) {
    std::string faces;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (static_cast<int>(mesh.triangle_material[t]) != r) continue;
      const auto& f = mesh.triangles[t];
      faces += (faces.empty() ? "" : " ") + std::to_string(f[0]) + " " + std::to_string(f[1]) +
               " " + std::to_string(f[2]) + " -1";
    }
    if (faces.empty()) continue;
    pugi::xml_node shape = humanoid.append_child("Shape");
    shape.append_attribute("containerField") = "skin";
    auto material = shape.append_child("Appearance").append_child("Material");
    material.append_attribute("diffuseColor") = triple(colors[r]).c_str();
    auto ifs = shape.append_child("IndexedFaceSet");
    ifs.append_attribute("coordIndex") = faces.c_str();
    ifs.append_child("Coordinate").append_attribute("USE") = "skin_points";
  }
  if (motion) add_motion(humanoid, skeleton, *motion);

  std::ostringstream out;
  doc.save(out, "  ", pugi::format_default, pugi::encoding_utf8);
  return out.str();
}

void write_x3d_humanoid(const std::filesystem::path& path, const std::string& name,
                        const Skeleton& skeleton, const BodyMesh& mesh,
                        const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors,
                        const Motion* motion) {
  write_text_atomic(path, format_x3d_humanoid(name, skeleton, mesh, colors, motion));
}

}  // namespace simcap
