#include "tracker/unzueta/part_model.h"

#include <Eigen/Eigenvalues>
#include <string>

#include "core/error.h"

namespace simcap::tracker {

PartModel::PartModel(const Skeleton& skeleton, const BodyMesh& mesh) {
  for (Effector e : kEffectors) {
    const int i = index_of(e);
    joint_[i] = skeleton.require(effector_joint(e));
    std::vector<int> segments = {joint_[i]};
    if (e == Effector::left_foot || e == Effector::right_foot) {
      const std::string side = e == Effector::left_foot ? "l_" : "r_";
      segments.push_back(skeleton.require(side + "metatarsophalangeal_2"));
    }
    if (e == Effector::pelvis) {
      // The belly's and back's distance from the root: half the torso's depth at root height.
      segments = {skeleton.require("sacroiliac"), joint_[i]};
    }
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> points;
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
      for (int s : segments) {
        if (mesh.vertex_segment[v] == s) points.push_back(mesh.vertices[v].cast<double>());
      }
    }
    if (points.size() < 4) {
      throw Error("part model: the body mesh has no " + std::string(effector_name(e)) +
                  " vertices (segment of " + std::string(effector_joint(e)) + ")");
    }
    for (const auto& p : points) sum += p;
    const Eigen::Vector3d mean = sum / static_cast<double>(points.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
    cov /= static_cast<double>(points.size());
    const double smallest = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues()(0);
    radius_[i] = std::sqrt(2.0 * std::max(smallest, 0.0));
    offset_[i] = e == Effector::pelvis ? Eigen::Vector3d::Zero()
                                       : Eigen::Vector3d(mean - skeleton[joint_[i]].center);
  }
}

Eigen::Vector3d PartModel::centre(Effector e, const std::vector<Eigen::Quaterniond>& rotation,
                                  const std::vector<Eigen::Vector3d>& position) const {
  const int j = joint(e);
  return position[j] + rotation[j] * centre_offset(e);
}

Eigen::Vector3d PartModel::joint_from_centre(
    Effector e, const Eigen::Vector3d& centre,
    const std::vector<Eigen::Quaterniond>& rotation) const {
  return centre - rotation[joint(e)] * centre_offset(e);
}

}  // namespace simcap::tracker
