// The CCD baseline of Table 10: it follows a walking humanoid's end-effectors within the thesis'
// 1 cm tolerance, keeps hinges hinges and never leaves the joint limits.
#include <gtest/gtest.h>

#include <algorithm>

#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/tracker/unzueta/ik_solver_checks.h"
#include "tracker/unzueta/ccd.h"

namespace simcap {
namespace {

using testing::world_positions;

TEST(Ccd, FollowsAWalkWithinItsTolerance) {
  const Skeleton skeleton = build_humanoid();
  const SikBody body(skeleton);
  ProceduralSpec walk;
  walk.duration_s = 2.0;
  const Motion motion = generate_procedural(walk, skeleton, 120.0);
  CcdSolver solver(body);
  std::vector<double> errors;
  for (const Pose& truth : motion.frames) {
    const SikTargets t = body.targets(world_positions(body, truth));
    const auto p = world_positions(body, solver.solve(t));
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
  CcdSolver solver(body);
  testing::expect_within_limits(solver, 2, 300);
  // Without limits the elbows and knees still turn about their hinge axes only.
  const auto rest = world_positions(body, Pose::neutral(body.skeleton()));
  CcdOptions free;
  free.limits = false;
  CcdSolver unlimited(body, free);
  SikTargets t = body.targets(rest);
  t.wrist[kLeft] = rest[body.arm(kLeft).a] + Eigen::Vector3d(0.1, 0.1, 0.3);
  const Pose& pose = unlimited.solve(t);
  const int elbow = body.arm(kLeft).b;
  const Eigen::AngleAxisd turn(pose.rotations[elbow]);
  EXPECT_GT(turn.angle(), 0.5);
  EXPECT_NEAR(std::abs(turn.axis().dot(limits[elbow].pole)), 1.0, 1e-9);
}

}  // namespace
}  // namespace simcap
