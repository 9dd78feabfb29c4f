// The Jacobian baselines of Table 10: DLS's damping trades convergence for stability, limits hold,
// with light damping DLS converges on a walking humanoid's end-effectors, and the pseudoinverse,
// DLS by SVD and SDLS reach a reachable target.
#include <gtest/gtest.h>

#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/tracker/unzueta/ik_solver_checks.h"
#include "tracker/unzueta/dls.h"

namespace simcap {
namespace {

using testing::world_positions;

double largest_error(const SikBody& body, const Pose& pose, const SikTargets& t) {
  const auto p = world_positions(body, pose);
  double worst = (p[body.head()] - t.head).norm();
  for (int side : {kLeft, kRight}) {
    worst = std::max(worst, (p[body.arm(side).c] - t.wrist[side]).norm());
    worst = std::max(worst, (p[body.leg(side).c] - t.ankle[side]).norm());
  }
  return worst;
}

class DlsTest : public ::testing::Test {
 protected:
  Skeleton skeleton = build_humanoid();
  SikBody body{skeleton};
  std::vector<Eigen::Vector3d> rest = world_positions(body, Pose::neutral(skeleton));
  SikTargets neutral = body.targets(rest);
  // An arm raised forward: reachable, 30 cm from where the neutral wrist is.
  SikTargets reach() const {
    SikTargets t = neutral;
    t.wrist[kLeft] = rest[body.arm(kLeft).a] + Eigen::Vector3d(0.05, -0.25, 0.35);
    return t;
  }
};

TEST_F(DlsTest, DampingShortensTheStep) {
  const SikTargets t = reach();
  // How far one iteration turns the joints away from the neutral pose.
  auto one_step = [&](double damping) {
    DlsOptions o;
    o.damping = damping;
    o.max_iterations = 1;
    o.limits = false;
    o.pelvis_weights = {0.0, 1.0, 0.0};  // the moved wrist must not turn the pelvis
    DlsSolver solver(body, o);
    const Pose& pose = solver.solve(t);
    double turned = 0.0;
    for (int j = 1; j < body.size(); ++j) turned += Eigen::AngleAxisd(pose.rotations[j]).angle();
    return turned;
  };
  const double light = one_step(0.05), thesis = one_step(0.75), heavy = one_step(100.0);
  EXPECT_GT(light, thesis);
  EXPECT_GT(thesis, 0.05);
  EXPECT_LT(heavy, 1e-3);  // lambda >> |J|: hardly a move
}

TEST_F(DlsTest, ConvergesOnAWalkWithLightDamping) {
  ProceduralSpec walk;
  walk.duration_s = 2.0;
  const Motion motion = generate_procedural(walk, skeleton, 120.0);
  DlsOptions o;
  o.damping = 0.05;
  DlsSolver solver(body, o);
  int converged = 0;
  for (const Pose& truth : motion.frames) {
    const SikTargets t = body.targets(world_positions(body, truth));
    converged += largest_error(body, solver.solve(t), t) < 0.01;
  }
  EXPECT_GT(converged, 0.9 * motion.frames.size());
}

TEST_F(DlsTest, NeverLeavesTheLimits) {
  DlsSolver solver(body);
  testing::expect_within_limits(solver, 4, 200);
}

class JacobianSolverTest : public DlsTest, public ::testing::WithParamInterface<JacobianUpdate> {};

TEST_P(JacobianSolverTest, ReachesAReachableWrist) {
  const SikTargets t = reach();
  DlsOptions o;
  o.update = GetParam();
  o.damping = 0.05;  // DLS variants: light damping, so they converge within the 20 iterations
  o.limits = false;
  o.min_improvement = 0.0;
  o.pelvis_weights = {0.0, 1.0, 0.0};
  DlsSolver solver(body, o);
  EXPECT_EQ(solver.name(), jacobian_update_name(GetParam()));
  // The neutral arm hangs straight, a singular pose where the plain pseudoinverse overshoots (the
  // jerkiness the thesis reports); a first frame halfway there bends it, as a motion would.
  SikTargets halfway = t;
  halfway.wrist[kLeft] = 0.5 * (t.wrist[kLeft] + neutral.wrist[kLeft]);
  solver.solve(halfway);
  EXPECT_LT(largest_error(body, solver.solve(t), t), o.tolerance);
}

TEST_P(JacobianSolverTest, NeverLeavesTheLimits) {
  DlsOptions o;
  o.update = GetParam();
  DlsSolver solver(body, o);
  testing::expect_within_limits(solver, 5, 100);
}

INSTANTIATE_TEST_SUITE_P(Updates, JacobianSolverTest,
                         ::testing::Values(JacobianUpdate::kPseudoinverse, JacobianUpdate::kDls,
                                           JacobianUpdate::kDlsSvd, JacobianUpdate::kSdls,
                                           JacobianUpdate::kPrioritized),
                         [](const auto& info) {
                           std::string name(jacobian_update_name(info.param));
                           std::erase(name, '-');
                           return name;
                         });

}  // namespace
}  // namespace simcap
