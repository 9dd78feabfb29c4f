// Moschini's hierarchical articulated ICP (§4.3, Alg. 2): fits the stick model to centerline
// points one segment at a time from the torso down, keeping joints connected and in range.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/pose_refiner.h"
#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {

// The thesis leaves ε, the stopping threshold and the iteration cap open; these values were
// chosen on rendered sequences (see tracker/MOSCHINI.md).
struct IcpOptions {
  double descendant_weight = 0.3;  // ε, the W entry of points matched to a descendant stick
  // W entry of two "anchor" pairs off the stick's axis that map onto themselves. When the
  // matched points are collinear (a straight limb), the spin about the stick is undetermined and
  // an SVD would pick it arbitrarily; the anchors keep it where it was unless data say otherwise.
  double anchor_weight = 0.05;
  double x84_k = 3.5;          // X84: reject |e - med e| > k · 1.4826 · MAD (large side only)
  double x84_floor_m = 0.02;   // ...but never a point closer than this
  int max_iterations = 6;      // per segment
  double converged_m = 0.003;  // stop when the weighted mean distance falls below this...
  double min_improvement_m = 0.0003;  // ...or improves by less than this in one iteration
  int sweeps = 1;                     // traversals of the tree (the thesis: one)
  RefineOptions refine;               // the joint refinement after the traversal
};

struct IcpResult {
  double mean_distance_m = 0;  // mean closest-stick distance of the X84 inliers at the end
  double inlier_fraction = 0;
  int iterations = 0;  // total over all segments
};

class ArticulatedIcp {
 public:
  ArticulatedIcp(const StickModel& model, const BodySurface& surface,
                 const IcpOptions& options = {});
  // Registers the model, starting at `pose`, onto the targets' centerline points (Alg. 2), then
  // refines all parameters jointly against every target (PoseRefiner); updates `pose`.
  IcpResult fit(const IcpTargets& targets, StickPose& pose) const;
  // Residual statistics of `pose` against `points` without moving it.
  IcpResult evaluate(const std::vector<Eigen::Vector3d>& points, const StickPose& pose) const;
  const IcpOptions& options() const { return options_; }

 private:
  int fit_segment(int segment, const std::vector<Eigen::Vector3d>& points, StickPose& pose,
                  std::vector<ClosestStick>& closest, std::vector<double>& distances) const;
  const StickModel* model_;
  IcpOptions options_;
  PoseRefiner refiner_;
};

}  // namespace simcap::tracker
