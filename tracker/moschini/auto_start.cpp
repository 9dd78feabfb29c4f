#include "tracker/moschini/auto_start.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/grid_search.h"
#include "tracker/moschini/pose_init.h"
#include "tracker/moschini/surface_fit.h"

namespace simcap::tracker {
namespace {

// Of `upright` turned about the vertical through its torso's centroid by every 360/turns
// degrees, each fitted again, as a recovery hypothesis and to the silhouettes alone, and
// tracked through `first`, the one whose silhouette cost is least, as fitted to the first frame.
StickPose choose_heading(const StickPose& upright, const BodyDimensions& dims,
                         const std::vector<Observation>& first, const TrackerOptions& options,
                         const AutoStartOptions& search) {
  StickPose best = upright;
  double least_cost = std::numeric_limits<double>::infinity();
  const int frames = std::min<int>(search.frames, static_cast<int>(first.size()));
  for (int k = 0; k < search.turns; ++k) {
    StickPose turned = upright;
    turned.R0 =
        Eigen::AngleAxisd(2 * std::numbers::pi * k / search.turns, Eigen::Vector3d::UnitY()) *
        upright.R0;
    // Fitted by the joint refinement, the centerline's centroids between merged parts may lead
    // the limbs astray (arms held across the front: every fit of the four turns ended 56 to
    // 180 degrees off); fitted to the silhouettes alone, the true heading costs 7 times less.
    for (const bool by_silhouettes : {false, true}) {
      MoschiniTracker tracker(dims, typical_surface(dims), options);
      tracker.start(by_silhouettes ? tracker.fit_hypothesis_to_silhouettes(first.front(), turned)
                                   : tracker.fit_hypothesis(first.front(), turned));
      StickPose start;
      double cost = 0;
      for (int f = 0; f < frames; ++f) {
        const StickPose pose = tracker.step(first[f]).pose;
        if (f == 0) start = pose;
        cost += tracker.silhouette_score(pose, first[f]);
      }
      if (cost < least_cost) least_cost = cost, best = start;
    }
  }
  return best;
}

}  // namespace

FittedBody fit_body(const BodyDimensions& dims, const TrackerOptions& options,
                    const StickPose& pose, const Observation& obs) {
  const StickModel model(dims, options.joints, options.urdf_limits);
  FittedBody body{dims, {}};
  body.dims.centerline_offset = measure_centerline_offsets(model, pose, obs.points);
  body.surface = fit_surface(model, pose, typical_surface(dims), obs.rays, obs.views);
  return body;
}

AutoStart auto_start(const std::vector<Observation>& first, const TrackerOptions& options,
                     const AutoStartOptions& search) {
  std::vector<double> tops;
  for (const Observation& obs : first) {
    if (obs.hull.count > 0) tops.push_back(upright_cue(obs.hull, {}).top_y);
  }
  if (tops.empty()) throw Error("--init auto found no body in the first frames' hulls");
  std::nth_element(tops.begin(), tops.begin() + tops.size() / 2, tops.end());
  const double height = tops[tops.size() / 2];
  // From upright hypotheses with typical capsules the coarse sampling of the hypotheses' stage
  // finds the arms less often: every ray and the final outline step here.
  TrackerOptions fine = options;
  fine.icp.refine.ray_every = options.polish.ray_every;
  fine.icp.refine.rim_step_m = options.polish.rim_step_m;
  auto dims_of = [&](double scale, double shoulders) {
    BodyDimensions d = dimensions_from_height(scale * height);
    d.d_s = shoulders;
    return d;
  };
  BodyDimensions dims = dimensions_from_height(height);
  MoschiniTracker finder(dims, typical_surface(dims), fine);
  finder.start_upright(first.front());
  const StickPose upright =
      choose_heading(finder.step(first.front()).pose, dims, first, fine, search);
  // The cost of tracking the first frames from that pose with other proportions: the joint
  // angles carry over, the sticks' lengths and the shoulders' height do not. Each is scored with
  // the capsules it would be tracked with, fitted on the first frame: typical capsules put the
  // shoulders high (d_s 0.97-1.05 on the suite's bodies of 0.89; 1.23-1.28 on CMU's of 1.17).
  const int frames = std::min<int>(search.frames, static_cast<int>(first.size()));
  auto cost = [&](const BodyDimensions& d) {
    MoschiniTracker tracker(d, typical_surface(d), fine);
    tracker.start(upright);
    const StickPose start = tracker.step(first.front()).pose;
    const FittedBody body = fit_body(d, fine, start, first.front());
    TrackerOptions trusted = fine;
    trusted.trust_silhouettes = true;
    MoschiniTracker fitted(body.dims, body.surface, trusted);
    fitted.start(start);
    double total = 0;
    for (int f = 0; f < frames; ++f) {
      total += fitted.silhouette_score(fitted.step(first[f]).pose, first[f]);
    }
    return total;
  };
  const double shoulders =
      least_on_grid([&](double v) { return cost(dims_of(1.0, v)); }, search.shoulders_lo,
                    search.shoulders_hi, search.evaluations);
  const double scale = least_on_grid([&](double s) { return cost(dims_of(s, shoulders)); },
                                     search.scale_lo, search.scale_hi, search.evaluations);
  dims = dims_of(scale, shoulders);
  MoschiniTracker tracker(dims, typical_surface(dims), fine);
  tracker.start(upright);
  return {dims, tracker.step(first.front()).pose, ankle_height_from_height(scale * height)};
}

}  // namespace simcap::tracker
