// The CCD baseline of Table 10: it follows a walking humanoid's end-effectors within the thesis'
// 1 cm tolerance, keeps hinges hinges and never leaves the joint limits.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tracker/ccd.h"

namespace simcap {
namespace {

std::vector<Eigen::Vector3d> positions(const SikBody& body, const Pose& pose) {
  std::vector<Eigen::Quaterniond> r;
  std::vector<Eigen::Vector3d> p;
  body.forward(pose, r, p);
  return p;
}

TEST(Ccd, FollowsAWalkWithinItsTolerance) {
  const Skeleton skeleton = build_humanoid();
  const SikBody body(skeleton);
  ProceduralSpec walk;
  walk.duration_s = 2.0;
  const Motion motion = generate_procedural(walk, skeleton, 120.0);
  CcdSolver solver(body);
  std::vector<double> errors;
  for (const Pose& truth : motion.frames) {
    const SikTargets t = body.targets(positions(body, truth));
    const auto p = positions(body, solver.solve(t));
    for (int side : {kLeft, kRight}) {
      errors.push_back((p[body.arm(side).c] - t.wrist[side]).norm());
      errors.push_back((p[body.leg(side).c] - t.ankle[side]).norm());
    }
    // Half of the spine's residual goes to the pelvis, so both ends miss by the same amount.
    EXPECT_NEAR((p[body.root()] - t.pelvis).norm(), (p[body.head()] - t.head).norm(), 1e-9);
  }
  // CCD stops once within 1 cm, or when a sweep gains less than 1 mm.
  std::sort(errors.begin(), errors.end());
  EXPECT_LT(errors[errors.size() / 2], 0.01);
  EXPECT_LT(errors[errors.size() * 9 / 10], 0.02);
}

TEST(Ccd, KeepsHingesAndLimits) {
  const SikBody body(build_humanoid());
  const SikLimits limits(body);
  const auto rest = positions(body, Pose::neutral(body.skeleton()));
  const SikTargets neutral = body.targets(rest);
  CcdSolver solver(body);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> coord(-0.8, 0.8);
  for (int i = 0; i < 300; ++i) {
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
  // Without limits the elbows and knees still turn about their hinge axes only.
  CcdOptions free;
  free.limits = false;
  CcdSolver unlimited(body, free);
  SikTargets t = neutral;
  t.wrist[kLeft] = rest[body.arm(kLeft).a] + Eigen::Vector3d(0.1, 0.1, 0.3);
  const Pose& pose = unlimited.solve(t);
  const int elbow = body.arm(kLeft).b;
  const Eigen::AngleAxisd turn(pose.rotations[elbow]);
  EXPECT_GT(turn.angle(), 0.5);
  EXPECT_NEAR(std::abs(turn.axis().dot(limits[elbow].pole)), 1.0, 1e-9);
}

}  // namespace
}  // namespace simcap
