// --init auto's frames tracked again, backwards from the last one, once the body is measured:
// the first ones were tracked while the capsules and the shoulders' height were still guesses.
#pragma once

#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {

// A second tracker with the final body, going back in time from the forward pass's last pose.
// Each frame keeps whichever of the forward step and the backward one explains its silhouettes
// better with that body (tracking back can lose a limb where the forward pass held it); where
// the forward step does, tracking back goes on from its pose.
class TrackBack {
 public:
  TrackBack(const BodyDimensions& dims, const BodySurface& surface, const TrackerOptions& options,
            const StickPose& last);
  // `obs`: the frame before the one tracked back last (the last frame itself first); `step`:
  // the forward pass's step on it, replaced by the backward one when that explains it better.
  void step(const Observation& obs, TrackStep& step);

 private:
  MoschiniTracker tracker_;
};

}  // namespace simcap::tracker
