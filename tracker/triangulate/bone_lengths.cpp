#include "tracker/triangulate/bone_lengths.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "models/humanoid.h"

namespace simcap::tracker {

std::vector<Bone> rigid_bones(const KeypointLayout& layout) {
  const Skeleton body = build_humanoid();
  std::vector<int> joint(layout.size(), -1);
  for (int k = 0; k < layout.size(); ++k) {
    if (layout.keypoints[k].truth == TruthKind::hanim_joint) {
      joint[k] = body.find(layout.keypoints[k].truth_name);
    }
  }
  std::vector<Bone> bones;
  const double unknown = std::numeric_limits<double>::quiet_NaN();
  for (int a = 0; a < layout.size(); ++a) {
    for (int b = a + 1; b < layout.size(); ++b) {
      if (joint[a] < 0 || joint[b] < 0) continue;
      const int pa = body[joint[a]].parent, pb = body[joint[b]].parent;
      if (pa == joint[b] || pb == joint[a] || (pa >= 0 && pa == pb)) {
        bones.push_back({a, b, unknown});
      }
    }
  }
  return bones;
}

void measure_bone_lengths(std::vector<Bone>& bones,
                          const std::vector<std::vector<std::optional<Eigen::Vector3d>>>& frames) {
  for (Bone& bone : bones) {
    std::vector<double> d;
    for (const auto& f : frames) {
      if (f[bone.a] && f[bone.b]) d.push_back((*f[bone.a] - *f[bone.b]).norm());
    }
    bone.length = std::numeric_limits<double>::quiet_NaN();
    if (d.empty()) continue;
    const auto mid = d.begin() + static_cast<long>(d.size() / 2);
    std::nth_element(d.begin(), mid, d.end());
    bone.length = *mid;
    if (d.size() % 2 == 0) bone.length = 0.5 * (bone.length + *std::max_element(d.begin(), mid));
  }
}

void project_onto_bones(std::vector<std::optional<Eigen::Vector3d>>& keypoints,
                        const std::vector<Eigen::Matrix3d>& information,
                        const std::vector<Bone>& bones) {
  // The unknowns: the keypoints of the bones that apply, each once.
  std::vector<int> slot(keypoints.size(), -1), members;
  std::vector<Eigen::Matrix3d> covariance;
  std::vector<const Bone*> active;
  const auto usable = [&](int k) {
    if (!keypoints[k]) return false;
    if (slot[k] >= 0) return true;
    Eigen::FullPivLU<Eigen::Matrix3d> lu(information[k]);
    if (lu.rank() < 3) return false;
    slot[k] = static_cast<int>(members.size());
    members.push_back(k);
    covariance.push_back(lu.inverse());
    return true;
  };
  for (const Bone& bone : bones) {
    if (std::isfinite(bone.length) && bone.length > 0 && usable(bone.a) && usable(bone.b)) {
      active.push_back(&bone);
    }
  }
  if (active.empty()) return;
  const int n = static_cast<int>(members.size()), m = static_cast<int>(active.size());
  Eigen::VectorXd y(3 * n), x(3 * n);
  for (int i = 0; i < n; ++i) y.segment<3>(3 * i) = *keypoints[members[i]];
  x = y;
  // min ½(x−y)ᵀW(x−y) s.t. c(x) = 0, linearized at x: x + d with C d = −c,
  // d = y − x − W⁻¹Cᵀλ, (C W⁻¹ Cᵀ) λ = c + C (y − x).
  for (int iteration = 0; iteration < 50; ++iteration) {
    Eigen::MatrixXd c_jac = Eigen::MatrixXd::Zero(m, 3 * n), w_inv_ct(3 * n, m);
    Eigen::VectorXd c(m);
    for (int i = 0; i < m; ++i) {
      const int sa = slot[active[i]->a], sb = slot[active[i]->b];
      const Eigen::Vector3d v = x.segment<3>(3 * sa) - x.segment<3>(3 * sb);
      const double len = v.norm();
      if (!(len > 1e-12)) return;
      c(i) = len - active[i]->length;
      c_jac.block<1, 3>(i, 3 * sa) = v.transpose() / len;
      c_jac.block<1, 3>(i, 3 * sb) = -v.transpose() / len;
    }
    for (int i = 0; i < n; ++i) {
      w_inv_ct.middleRows<3>(3 * i) = covariance[i] * c_jac.middleCols<3>(3 * i).transpose();
    }
    const Eigen::MatrixXd s = c_jac * w_inv_ct;
    const Eigen::VectorXd lambda = s.ldlt().solve(c + c_jac * (y - x));
    const Eigen::VectorXd next = y - w_inv_ct * lambda;
    const double step = (next - x).cwiseAbs().maxCoeff();
    x = next;
    if (step < 1e-12) break;
  }
  for (int i = 0; i < n; ++i) keypoints[members[i]] = x.segment<3>(3 * i);
}

}  // namespace simcap::tracker
