#include "tracker/moschini/track_back.h"

namespace simcap::tracker {

void track_back(const BodyDimensions& dims, const BodySurface& surface,
                const TrackerOptions& options, std::vector<HeldFrame>& frames) {
  if (frames.empty()) return;
  MoschiniTracker back(dims, surface, options);
  back.start(frames.back().step.pose);
  for (auto it = frames.rbegin(); it != frames.rend(); ++it) {
    TrackStep step = back.step(*it->obs);
    if (back.silhouette_score(step.pose, *it->obs) < back.silhouette_score(it->step.pose, *it->obs))
      it->step = std::move(step);
  }
}

}  // namespace simcap::tracker
