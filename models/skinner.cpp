#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <string>

#include "core/error.h"
#include "models/body_mesh.h"
#include "models/pose.h"

namespace simcap {
namespace {

// Row-major 3x4 skinning matrix (joint world transform times inverse bind), in float so that the
// per-vertex loop runs in single precision.
struct SkinMatrix {
  float m[12];
};

// Vertices per task: large enough to amortize scheduling, small enough to balance two cores.
constexpr size_t kGrain = 2048;

}  // namespace

Skinner::Skinner(const Skeleton& skeleton, const BodyMesh& mesh) : mesh_(&mesh) {
  const size_t n = mesh.vertices.size();
  if (mesh.influence_joint.size() != n || mesh.influence_weight.size() != n) {
    throw Error("skinner: the mesh has " + std::to_string(n) + " vertices but " +
                std::to_string(mesh.influence_joint.size()) + " influence sets");
  }
  for (const auto& joints : mesh.influence_joint) {
    for (std::uint16_t j : joints) {
      if (j >= skeleton.size()) {
        throw Error("skinner: influence joint " + std::to_string(j) + " is not in the skeleton (" +
                    std::to_string(skeleton.size()) + " joints)");
      }
    }
  }
  for (const Eigen::Isometry3d& g : forward_kinematics(skeleton, Pose::neutral(skeleton))) {
    inverse_bind_.push_back(g.inverse());
  }
}

int Skinner::vertex_count() const {
  return static_cast<int>(mesh_->vertices.size());
}

void Skinner::skin(const std::vector<Eigen::Isometry3d>& joint_world, float* out) const {
  if (joint_world.size() != inverse_bind_.size()) {
    throw Error("skinner: got " + std::to_string(joint_world.size()) +
                " joint transforms for a skeleton of " + std::to_string(inverse_bind_.size()));
  }
  std::vector<SkinMatrix> matrices(joint_world.size());
  for (size_t j = 0; j < joint_world.size(); ++j) {
    const Eigen::Matrix<double, 3, 4> m = (joint_world[j] * inverse_bind_[j]).matrix().topRows<3>();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) matrices[j].m[4 * r + c] = static_cast<float>(m(r, c));
    }
  }
  const Eigen::Vector3f* vertices = mesh_->vertices.data();
  const auto* joints = mesh_->influence_joint.data();
  const auto* weights = mesh_->influence_weight.data();
  const SkinMatrix* mats = matrices.data();
  const size_t n = mesh_->vertices.size();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      // Most vertices lie away from joints and have a single influence of weight exactly 1
      // (the others then being 0): they take that matrix as it is.
      float blended[12];
      const float* m = mats[joints[i][0]].m;
      if (weights[i][0] != 1.0f) {
        const float w0 = weights[i][0];
        for (int e = 0; e < 12; ++e) blended[e] = w0 * m[e];
        for (int k = 1; k < 4; ++k) {
          const float* mk = mats[joints[i][k]].m;
          const float wk = weights[i][k];
          for (int e = 0; e < 12; ++e) blended[e] += wk * mk[e];
        }
        m = blended;
      }
      const float x = vertices[i].x(), y = vertices[i].y(), z = vertices[i].z();
      float* o = out + 3 * i;
      for (int r = 0; r < 3; ++r) {
        const float* row = m + 4 * r;
        o[r] = row[0] * x + row[1] * y + row[2] * z + row[3];
      }
    }
  });
  out[3 * n] = 0.0f;
}

}  // namespace simcap
