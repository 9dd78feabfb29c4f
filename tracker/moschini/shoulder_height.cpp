#include "tracker/moschini/shoulder_height.h"

#include "core/error.h"
#include "tracker/moschini/grid_search.h"
#include "tracker/moschini/pose_refiner.h"

namespace simcap::tracker {

ShoulderHeight shoulders_from_arms(const BodyDimensions& dims, const BodySurface& surface,
                                   const TrackerOptions& options,
                                   const std::vector<TrackedObservation>& frames, double lo,
                                   double hi, int evaluations) {
  if (frames.empty()) throw Error("shoulders_from_arms: no frames");
  RefineOptions arms = options.polish;
  arms.arms_only = true;
  // The summed cost of the arms of `frames` refitted from shoulders at height d_s (`last`: the
  // last frame's fit).
  auto cost = [&](double d_s, StickPose* last) {
    BodyDimensions d = dims;
    d.d_s = d_s;
    const StickModel model(d, options.joints, options.urdf_limits);
    const PoseRefiner refiner(model, surface, arms);
    double total = 0;
    for (const TrackedObservation& frame : frames) {
      const IcpTargets targets = MoschiniTracker::targets_of(*frame.obs);
      StickPose pose = frame.pose;
      refiner.refine(targets, pose);
      total += refiner.cost(targets, pose);
      if (last) *last = pose;
    }
    return total;
  };
  ShoulderHeight out;
  out.d_s = least_on_grid([&](double v) { return cost(v, nullptr); }, lo, hi, evaluations);
  cost(out.d_s, &out.last);
  return out;
}

}  // namespace simcap::tracker
