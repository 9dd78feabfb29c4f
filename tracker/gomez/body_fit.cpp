// Skeleton sizing and joint fitting (body_fit.h).
#include "tracker/gomez/body_fit.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/pose.h"

namespace simcap::tracker::gomez {
namespace {

const Eigen::Vector3d* find_point(const std::vector<NamedPoint>& joints, const std::string& name) {
  for (const NamedPoint& p : joints) {
    if (p.joint == name) return &p.position;
  }
  return nullptr;
}

}  // namespace

Skeleton sized_humanoid(const std::vector<NamedPoint>& joints) {
  const Skeleton unit = build_humanoid({1.75, {}});
  std::vector<double> ratios;
  std::vector<double> length(unit.size(), -1.0);
  for (int j = 1; j < unit.size(); ++j) {
    const Eigen::Vector3d* a = find_point(joints, unit[j].name);
    const Eigen::Vector3d* b = find_point(joints, unit[unit[j].parent].name);
    const double model = unit.offset(j).norm();
    if (!a || !b || model < 0.01) continue;
    length[j] = (*a - *b).norm();
    ratios.push_back(length[j] / model);
  }
  if (ratios.empty()) {
    throw Error("monocular body: no bone of the humanoid can be measured from the given joints");
  }
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const double height = std::clamp(1.75 * ratios[ratios.size() / 2], 0.6, 2.5);
  const Skeleton base = build_humanoid({height, {}});
  Skeleton out;
  for (int j = 0; j < base.size(); ++j) {
    Joint joint = base[j];
    if (j > 0) {
      Eigen::Vector3d offset = base.offset(j);
      if (length[j] > 0) offset *= length[j] / offset.norm();
      joint.center = out[joint.parent].center + offset;
    }
    out.add(joint);
  }
  return out;
}

State start_from_joints(const BodyDofs& dofs, const std::vector<NamedPoint>& joints) {
  State x = State::Zero(dofs.size());
  const Eigen::Vector3d* root = find_point(joints, "humanoid_root");
  for (int i = 0; i < dofs.size(); ++i) {
    if (dofs[i].translation && root) x[i] = (*root)[dofs[i].axis];
  }
  const Eigen::Vector3d* l = find_point(joints, "l_hip");
  const Eigen::Vector3d* r = find_point(joints, "r_hip");
  const int turn = dofs.find("root_turn");
  if (l && r && turn >= 0) {
    const Eigen::Vector3d left = *l - *r;
    x[turn] = std::atan2(-left.z(), left.x());
  }
  return dofs.clamp(x);
}

State fit_joints(const BodyDofs& dofs, const std::vector<NamedPoint>& joints, const State& start,
                 int iterations) {
  const Skeleton& s = dofs.skeleton();
  std::vector<std::pair<int, Eigen::Vector3d>> targets;
  for (const NamedPoint& p : joints) {
    const int j = s.find(p.joint);
    if (j >= 0) targets.emplace_back(j, p.position);
  }
  const int n = dofs.size(), m = 3 * static_cast<int>(targets.size());
  const auto residual = [&](const State& x) {
    const auto g = forward_kinematics(s, dofs.pose(x));
    Eigen::VectorXd r(m);
    for (size_t k = 0; k < targets.size(); ++k) {
      r.segment<3>(3 * k) = g[targets[k].first].translation() - targets[k].second;
    }
    return r;
  };
  State x = dofs.clamp(start);
  Eigen::VectorXd r = residual(x);
  double cost = r.squaredNorm(), lambda = 1e-3;
  Eigen::MatrixXd J(m, n);
  for (int it = 0; it < iterations && m > 0; ++it) {
    const double h = 1e-6;
    for (int i = 0; i < n; ++i) {
      State y = x;
      y[i] += h;
      J.col(i) = (residual(y) - r) / h;
    }
    const Eigen::MatrixXd JtJ = J.transpose() * J;
    const Eigen::VectorXd g = J.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 10 && !improved; ++tries) {
      Eigen::MatrixXd A = JtJ;
      A.diagonal() += lambda * (JtJ.diagonal().array() + 1e-9).matrix();
      const State y = dofs.clamp(x - A.ldlt().solve(g));
      const Eigen::VectorXd ry = residual(y);
      if (ry.squaredNorm() < cost) {
        x = y;
        r = ry;
        improved = cost - ry.squaredNorm() > 1e-14;
        cost = ry.squaredNorm();
        lambda = std::max(1e-9, lambda / 3);
        if (!improved) return x;
      } else {
        lambda *= 4;
      }
    }
    if (!improved) break;
  }
  return x;
}

}  // namespace simcap::tracker::gomez
