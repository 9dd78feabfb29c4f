#include "tests/tracker/unzueta/ik_solver_checks.h"

#include <gtest/gtest.h>

#include <random>

#include "tracker/unzueta/sik_limits.h"

namespace simcap::testing {

std::vector<Eigen::Vector3d> world_positions(const SikBody& body, const Pose& pose) {
  std::vector<Eigen::Quaterniond> r;
  std::vector<Eigen::Vector3d> p;
  body.forward(pose, r, p);
  return p;
}

void expect_within_limits(IkSolver& solver, unsigned seed, int trials) {
  const SikBody& body = solver.body();
  const SikLimits limits(body);
  const SikTargets neutral = body.targets(world_positions(body, Pose::neutral(body.skeleton())));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> coord(-0.8, 0.8);
  for (int i = 0; i < trials; ++i) {
    SikTargets t = neutral;
    for (int side : {kLeft, kRight}) {
      t.wrist[side] = neutral.pelvis + Eigen::Vector3d(coord(rng), coord(rng), coord(rng));
      t.ankle[side] = neutral.pelvis + Eigen::Vector3d(coord(rng), coord(rng) - 0.5, coord(rng));
    }
    const Pose& pose = solver.solve(t);
    for (int j = 0; j < body.size(); ++j) {
      EXPECT_LT(limits.excess(j, pose.rotations[j]), 1e-9) << body.skeleton()[j].name;
    }
  }
}

}  // namespace simcap::testing
