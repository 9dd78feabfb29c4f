// Joint Levenberg-Marquardt refinement of a stick pose against all of a frame's targets at
// once, run after Moschini's per-segment ICP; also scores poses for hypothesis tests.
#pragma once

#include <vector>

#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {

// Not in the thesis, which notes that in its hierarchical ICP an error in one limb "propagates
// downward without recovery": the torso is fitted first, pulled by limbs still in the previous
// frame's pose, and never revisited. Weights are per residual, relative to a centerline point.
struct RefineOptions {
  int iterations = 5;
  double tolerance = 1e-3;  // stop when a step lowers the cost by less than this fraction
  // Initial Levenberg damping relative to the mean diagonal of J^T J (adapted after each step).
  double damping = 0.01;
  double x84_k = 3.5;
  double x84_floor_m = 0.02;
  double centerline_weight = 1.0;   // per centerline point
  double containment_weight = 1.0;  // per stick sample off the hull
  int containment_search = 6;       // voxels searched around a sample for the nearest occupied
  // Per silhouette ray, on its distance outside the nearest capsule (0 when a capsule meets it).
  double ray_weight = 1.0;
  int ray_every = 1;  // uses every n-th ray of the targets' (they come row by row per camera)
  // Rays passing farther from every capsule count at this miss, without pulling: a ray this far
  // from the body's parts cannot tell where they should go.
  double ray_max_miss_m = 0.6;
  // Rays passing this deep inside a capsule count as met for the whole iteration, trial steps
  // included, without being recomputed (exact at the pose they were associated at; a step that
  // moves a surface this far is rare, and the next iteration looks again).
  double settled_depth_m = 0.03;
  // Per point sampled every `rim_step_m` along each capsule's outline as each camera sees it, on
  // its distance outside that camera's silhouette (0 inside).
  double rim_weight = 1.0;
  double rim_step_m = 0.04;
  // A weak prior towards the neutral pose on hip abduction and twist, as a residual of this
  // many metres per radian: people walk and stand with their legs swinging fore and aft. A
  // torso turned away from the true heading must spread the legs sideways to reach their data,
  // so the prior turns the torso back (its heading is otherwise barely observed: 4 corner views
  // give a near-round hull around a torso, and the arms often merge with it).
  double leg_prior_m_per_rad = 0.1;
  // A pull of every parameter towards the prediction (IcpTargets::prediction, else where the
  // refinement started), as this many metres per radian (and per metre for the torso's
  // translation): directions the data barely observe then stay put instead of drifting, and a
  // limb hidden against the torso does not jump to another hidden place.
  double motion_prior_m_per_rad = 0.05;
  // Only the arms' angles (shoulders, elbows, wrists) move; the torso, head and legs stay where
  // the refinement starts: --init auto measures the shoulders' height by how well the arms hung
  // from it explain the silhouettes (shoulder_height.h).
  bool arms_only = false;
};

class PoseRefiner {
 public:
  PoseRefiner(const StickModel& model, const BodySurface& surface,
              const RefineOptions& options = {});
  // Gauss-Newton steps on the torso's translation and rotation and all joint angles; the angles
  // stay in their ranges.
  void refine(const IcpTargets& targets, StickPose& pose) const;
  // The weighted sum of squared residuals refine() minimizes, per residual; lower is better.
  double cost(const IcpTargets& targets, const StickPose& pose) const;
  // The gradient of cost() by [root translation, root rotation (a left increment about the
  // root), angles] as the normal equations build it, with targets.prediction as the motion
  // prior's anchor, as cost() has it. Outline targets are held fixed, as refine() holds them.
  Eigen::VectorXd gradient(const IcpTargets& targets, const StickPose& pose) const;
  // The indices of every `every`-th silhouette ray that passes farther than `min_miss_m` from
  // every capsule its colour allows: silhouette the pose leaves unexplained.
  std::vector<int> missed_rays(const IcpTargets& targets, const StickPose& pose, double min_miss_m,
                               int every) const;
  const RefineOptions& options() const { return options_; }

 private:
  struct Associations;
  // With `previous` (the last association of the same targets), each ray's capsule there is
  // tried first: the result is the same, found sooner.
  Associations associate(const IcpTargets& targets, const StickPose& pose,
                         const Associations* previous) const;
  // The cost at `pose` with fixed associations, and the normal equations when H and g are given
  // (`count`: how many residuals the cost averages). With `start`, adds the motion prior
  // towards it.
  double evaluate(const IcpTargets& targets, const Associations& a, const StickPose& pose,
                  const StickPose* start, Eigen::MatrixXd* H, Eigen::VectorXd* g,
                  int* count = nullptr) const;
  const StickModel* model_;
  BodySurface surface_;
  RefineOptions options_;
  std::array<std::vector<int>, kSegmentCount> chains_;  // StickModel::chain_angles per segment
};

}  // namespace simcap::tracker
