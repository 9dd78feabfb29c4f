#include "models/body_gltf.h"

#include "core/error.h"

namespace simcap {

std::vector<Eigen::Vector3f> vertex_normals(
    const std::vector<Eigen::Vector3f>& vertices,
    const std::vector<std::array<std::uint32_t, 3>>& triangles) {
  std::vector<Eigen::Vector3f> normals(vertices.size(), Eigen::Vector3f::Zero());
  for (const auto& t : triangles) {
    const Eigen::Vector3f n =
        (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
    for (const std::uint32_t v : t) normals[v] += n;
  }
  for (auto& n : normals) {
    if (n.norm() > 0) n.normalize();
  }
  return normals;
}

GltfBody add_gltf_body(GltfBuilder& builder, const std::string& name, const Skeleton& skeleton,
                       const BodyMesh& mesh,
                       const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors,
                       const Pose& pose, const JointNamer& namer) {
  if (static_cast<int>(pose.rotations.size()) != skeleton.size()) {
    throw Error("glTF body '" + name + "': the pose is not of its skeleton");
  }
  GltfBody body;
  for (int j = 0; j < skeleton.size(); ++j) {
    GltfBuilder::Node node;
    node.name = namer ? namer(skeleton[j].name) : skeleton[j].name;
    node.translation = j == 0 ? pose.root_position : skeleton.offset(j);
    node.rotation = pose.rotations[j];
    const int parent = skeleton[j].parent;
    body.joint_nodes.push_back(builder.add_node(node, parent < 0 ? -1 : body.joint_nodes[parent]));
  }
  std::vector<Eigen::Matrix4f> inverse_binds;
  for (const Joint& j : skeleton.joints()) {
    Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
    m.topRightCorner<3, 1>() = -j.center.cast<float>();
    inverse_binds.push_back(m);
  }
  const int skin = builder.add_skin(name, body.joint_nodes, inverse_binds, body.joint_nodes[0]);

  GltfBuilder::Vertices v;
  v.positions = mesh.vertices;
  v.normals = vertex_normals(mesh.vertices, mesh.triangles);
  v.joints = mesh.influence_joint;
  v.weights = mesh.influence_weight;
  // glTF wants the unused slots (weight 0) to name joint 0.
  for (size_t i = 0; i < v.joints.size(); ++i) {
    for (int k = 0; k < 4; ++k) {
      if (v.weights[i][k] == 0) v.joints[i][k] = 0;
    }
  }
  std::vector<GltfBuilder::Primitive> primitives;
  for (int r = 0; r < kMaterialRegionCount; ++r) {
    GltfBuilder::Primitive p;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (static_cast<int>(mesh.triangle_material[t]) != r) continue;
      p.indices.insert(p.indices.end(), mesh.triangles[t].begin(), mesh.triangles[t].end());
    }
    if (p.indices.empty()) continue;
    const std::string region(material_region_name(static_cast<MaterialRegion>(r)));
    p.material = builder.add_material(name + "_" + region, colors[r]);
    primitives.push_back(std::move(p));
  }
  GltfBuilder::Node skinned;
  skinned.name = name;
  skinned.mesh = builder.add_mesh(name, v, primitives);
  skinned.skin = skin;
  body.mesh_node = builder.add_node(skinned);
  return body;
}

std::vector<GltfBuilder::Channel> gltf_motion_channels(const GltfBody& body,
                                                       const Skeleton& skeleton,
                                                       const std::vector<Pose>& frames,
                                                       double fps) {
  if (frames.empty()) throw Error("glTF animation: no frames");
  std::vector<float> times;
  for (size_t f = 0; f < frames.size(); ++f) times.push_back(static_cast<float>(f / fps));
  std::vector<GltfBuilder::Channel> channels;
  GltfBuilder::Channel root{body.joint_nodes[0], false, times, {}};
  for (const Pose& p : frames) {
    root.values.emplace_back(p.root_position.cast<float>().homogeneous());
  }
  channels.push_back(std::move(root));
  for (int j = 0; j < skeleton.size(); ++j) {
    if (skeleton[j].is_site) continue;
    GltfBuilder::Channel c{body.joint_nodes[j], true, times, {}};
    Eigen::Quaterniond previous = Eigen::Quaterniond::Identity();
    for (const Pose& p : frames) {
      Eigen::Quaterniond q = p.rotations.at(j).normalized();
      // Consecutive keys on the same hemisphere, so that readers interpolate the short way.
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      c.values.emplace_back(q.coeffs().cast<float>());  // x y z w
    }
    channels.push_back(std::move(c));
  }
  return channels;
}

}  // namespace simcap
