// The CCD and KMA baselines of Table 10: CCD follows a walking humanoid's end-effectors within the
// thesis' 1 cm tolerance, keeps hinges hinges and never leaves the joint limits; KMA's limbs swivel
// to their references.
#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/tracker/unzueta/ik_solver_checks.h"
#include "tracker/unzueta/ccd.h"

namespace simcap {
namespace {

using testing::world_positions;

Motion walk(const Skeleton& skeleton, double seconds, double fps) {
  ProceduralSpec spec;
  spec.duration_s = seconds;
  return generate_procedural(spec, skeleton, fps);
}

TEST(Ccd, FollowsAWalkWithinItsTolerance) {
  const Skeleton skeleton = build_humanoid();
  const SikBody body(skeleton);
  const Motion motion = walk(skeleton, 2.0, 120.0);
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

TEST(Kma, BendsElbowsDownAndKneesForwardOfThePelvis) {
  // Zero swivel: each limb's middle joint lies in the half-plane from its root-to-end line toward
  // the pelvis' -Y (arms) or +Z (legs); the ends on reachable targets; within the limits.
  const Skeleton skeleton = build_humanoid();
  const SikBody body(skeleton);
  const Motion motion = walk(skeleton, 1.0, 30.0);
  CcdOptions free;
  free.limits = false;
  CcdSolver solver(body, free, CcdVariant::kma);
  EXPECT_EQ(solver.name(), "kma");
  std::vector<Eigen::Quaterniond> rotation;
  std::vector<Eigen::Vector3d> p;
  int reached = 0;
  for (const Pose& truth : motion.frames) {
    const SikTargets t = body.targets(world_positions(body, truth));
    body.forward(solver.solve(t), rotation, p);
    const Eigen::Matrix3d pelvis = rotation[body.root()].toRotationMatrix();
    for (int side : {kLeft, kRight}) {
      for (const auto& [limb, target, reference] :
           {std::tuple{&body.arm(side), t.wrist[side], Eigen::Vector3d(-pelvis.col(1))},
            std::tuple{&body.leg(side), t.ankle[side], Eigen::Vector3d(pelvis.col(2))}}) {
        // Unturned clavicles and a spine within CCD's tolerance can leave a wrist out of reach.
        const double reach = body.offset(limb->b).norm() + body.offset(limb->c).norm();
        if ((target - p[limb->a]).norm() < reach - 1e-3) {
          EXPECT_LT((p[limb->c] - target).norm(), 1e-6);
          ++reached;
        }
        const Eigen::Vector3d n = (p[limb->c] - p[limb->a]).normalized();
        const Eigen::Vector3d off = p[limb->b] - p[limb->a] - (p[limb->b] - p[limb->a]).dot(n) * n;
        const Eigen::Vector3d ref = reference - reference.dot(n) * n;
        EXPECT_NEAR(off.normalized().dot(ref.normalized()), 1.0, 1e-9);
      }
    }
  }
  EXPECT_GT(reached, static_cast<int>(motion.frames.size()));  // of 4 limbs per frame
  CcdSolver limited(body, {}, CcdVariant::kma);
  testing::expect_within_limits(limited, 3, 300);
}

}  // namespace
}  // namespace simcap
