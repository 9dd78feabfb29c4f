// --init auto's first frames tracked again, backwards, once the body is measured: they were
// tracked while the capsules and the shoulders' height were still guesses.
#pragma once

#include <memory>
#include <vector>

#include "tracker/moschini/moschini_tracker.h"

namespace simcap::tracker {

// A frame whose output waits, and the step the tracker took on it.
struct HeldFrame {
  std::shared_ptr<const Observation> obs;
  TrackStep step;
};

// Tracks `frames` (in time order) again from the last one's pose back to the first with the
// body `dims`, `surface`; each frame keeps whichever of its step and the backward one explains
// its silhouettes better with that body (tracking back can lose a limb where the forward pass
// held it).
void track_back(const BodyDimensions& dims, const BodySurface& surface,
                const TrackerOptions& options, std::vector<HeldFrame>& frames);

}  // namespace simcap::tracker
