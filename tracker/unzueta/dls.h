// The Jacobian baselines of Unzueta's Table 10 (§4.7.1): pseudoinverse, DLS, DLS with SVD, SDLS
// and PIK on ball joints as XYZ follower Euler angles and hinges.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "tracker/unzueta/ik_baseline_options.h"
#include "tracker/unzueta/jacobian_step.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_ik_solver.h"
#include "tracker/unzueta/sik_limits.h"
#include "tracker/unzueta/sik_pelvis.h"

namespace simcap {

struct DlsOptions : IkBaselineOptions {
  // The damping factor lambda of  dq = J^T (J J^T + lambda^2 I)^-1 e  is a length. The thesis
  // sets it "to 75" without a unit; read in centimetres, the unit its stopping rule is stated in
  // (1 cm, 1 mm), that is 0.75 m, which damps the slow directions of a body-sized Jacobian
  // (singular values of a few decimetres to a metre) as the thesis describes; in metres 75 would
  // freeze the body and in millimetres (0.075 m) barely damp it.
  double damping = 0.75;
  // The thesis runs all its Jacobian methods on the same model, limits and stopping rule; only
  // the update differs. kPrioritized is its PIK (§4.7.1): the root exactly on the pelvis target,
  // then ankles, wrists and head at decreasing priority by DLS with SVD, limits as inequality
  // constraints, and the null space drawn to a relaxed standing pose.
  JacobianUpdate update = JacobianUpdate::kDls;
};

class DlsSolver final : public IkSolver {
 public:
  explicit DlsSolver(SikBody body, DlsOptions options = {});
  DlsSolver(const DlsSolver&) = delete;
  DlsSolver& operator=(const DlsSolver&) = delete;

  std::string_view name() const override { return jacobian_update_name(options_.update); }
  const SikBody& body() const override { return body_; }
  const Pose& solve(const SikTargets& targets) override;
  void reset() override;

 private:
  struct Dof {
    int joint;
    int axis;  // 0, 1, 2: X, Y, Z follower Euler angle; -1: the joint's hinge axis
  };
  void pose_from_angles();
  // Places the root on the pelvis target, then moves it by half the head's error (thesis §4.2).
  void place_root(const SikTargets& targets);
  double largest_error(const SikTargets& targets) const;
  // Whether dofs [k, k + 3) (a ball joint) or dof k (a hinge) leave the limits at `angles`; then
  // `angles` gets the clamped values.
  bool clamp_joint(int k, Eigen::VectorXd& angles) const;
  // PIK's step: the prioritized step; a joint it would take past its limits is fixed on them
  // (its columns removed, its move taken out of the error) and the step recomputed, until none.
  Eigen::VectorXd pik_step(const Eigen::MatrixXd& jacobian, const Eigen::VectorXd& residual) const;

  DlsOptions options_;
  SikBody body_;
  SikLimits limits_;
  SikPelvisEstimator pelvis_;
  Pose pose_;
  std::vector<Eigen::Quaterniond> rotation_;
  std::vector<Eigen::Vector3d> position_;
  std::vector<Dof> dofs_;
  std::vector<int> ball_joints_, hinge_joints_;
  Eigen::VectorXd angles_;                   // one per dof
  Eigen::VectorXd relaxed_;                  // PIK's standing pose: elbows and knees a bit bent
  std::vector<std::vector<int>> effectors_;  // per dof: indices (0..4) of effectors it moves
  std::array<int, 5> effector_joint_{};      // head, wrists, ankles
};

}  // namespace simcap
