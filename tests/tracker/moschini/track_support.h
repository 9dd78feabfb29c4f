// Test support for the tracking loop: the same observation tracked for a few frames from a
// given start, in a working volume around the person.
#pragma once

#include "tracker/moschini/moschini_tracker.h"

namespace simcap::testing {

// The working volume the ring rig's tests carve: 1.2 m around the torso, from the floor below a
// standing person to a metre above the torso.
inline Eigen::AlignedBox3d volume_around(const tracker::StickPose& pose) {
  return {pose.t0 - Eigen::Vector3d(1.2, 1.1, 1.2), pose.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)};
}

// The pose tracked from `start` after `frames` steps of `obs`, without the filter (so that each
// step's fit is what is kept).
inline tracker::StickPose track_repeated(const tracker::BodyDimensions& dims,
                                         const tracker::BodySurface& surface,
                                         tracker::TrackerOptions options,
                                         const tracker::StickPose& start,
                                         const tracker::Observation& obs, int frames) {
  options.use_filter = false;
  tracker::MoschiniTracker tracker(dims, surface, options);
  tracker.start(start);
  tracker::StickPose pose = start;
  for (int frame = 0; frame < frames; ++frame) pose = tracker.step(obs).pose;
  return pose;
}

}  // namespace simcap::testing
