#include "tracker/unzueta/part_model.h"

#include <algorithm>
#include <string>

#include "core/error.h"

namespace simcap::tracker {
namespace {

// Enough vertices to average a part's surface; more only costs time every frame.
constexpr size_t kMaxVertices = 400;

}  // namespace

PartModel::PartModel(const Skeleton& skeleton, const BodyMesh& mesh) {
  // Skin vertices: those of a skin triangle (for the head, whose hair CFOF does not follow).
  std::vector<bool> skin(mesh.vertices.size(), false);
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (mesh.triangle_material[t] != MaterialRegion::skin) continue;
    for (std::uint32_t v : mesh.triangles[t]) skin[v] = true;
  }
  for (Effector e : kEffectors) {
    const int i = index_of(e);
    joint_[i] = skeleton.require(effector_joint(e));
    std::vector<int> segments = {joint_[i]};
    if (e == Effector::left_foot || e == Effector::right_foot) {
      const std::string side = e == Effector::left_foot ? "l_" : "r_";
      segments.push_back(skeleton.require(side + "metatarsophalangeal_2"));
    }
    if (e == Effector::pelvis) segments = {skeleton.require("sacroiliac"), joint_[i]};
    std::vector<Eigen::Vector3d> points;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      if (e == Effector::head && !skin[v]) continue;
      for (int s : segments) {
        if (mesh.vertex_segment[v] == s) points.push_back(mesh.vertices[v].cast<double>());
      }
    }
    if (points.size() < 4) {
      throw Error("part model: the body mesh has no " + std::string(effector_name(e)) +
                  " vertices (segment of " + std::string(effector_joint(e)) + ")");
    }
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : points) mean += p;
    mean /= static_cast<double>(points.size());
    const Eigen::Vector3d joint = skeleton[joint_[i]].center;
    offset_[i] = e == Effector::pelvis ? Eigen::Vector3d::Zero() : Eigen::Vector3d(mean - joint);
    const Eigen::Vector3d centre = joint + offset_[i];
    const size_t step = (points.size() + kMaxVertices - 1) / kMaxVertices;
    for (size_t k = 0; k < points.size(); k += step) vertices_[i].push_back(points[k] - centre);
  }
}

double PartModel::depth_behind_surface(Effector e, const Eigen::Quaterniond& rotation,
                                       const Eigen::Vector3d& ray, bool middle) const {
  // The side facing the camera: vertices nearer than the centre along the ray.
  const Eigen::Vector3d local = rotation.conjugate() * ray;
  double sum = 0, weight = 0, deepest = 0;
  for (const Eigen::Vector3d& v : vertices_[index_of(e)]) {
    const double d = -v.dot(local);
    if (d <= 0) continue;
    const double w = d / std::max(v.norm(), 1e-9);
    sum += w * d;
    weight += w;
    deepest = std::max(deepest, d);
  }
  if (middle) return deepest;
  return weight > 0 ? sum / weight : 0.0;
}

Eigen::Vector3d PartModel::joint_from_centre(
    Effector e, const Eigen::Vector3d& centre,
    const std::vector<Eigen::Quaterniond>& rotation) const {
  return centre - rotation[joint(e)] * centre_offset(e);
}

}  // namespace simcap::tracker
