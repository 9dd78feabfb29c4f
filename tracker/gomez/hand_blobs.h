// Where the hands may be in one frame: connected regions of the hands' colour class in the
// segmented working image, for the particle filter's image-driven hand proposals (H5 asked where
// the image puts a hand, not only around the last pose).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "tracker/gomez/frame_cues.h"

namespace simcap::tracker::gomez {

struct HandBlob {
  std::vector<Eigen::Vector2d> pixels;  // its working pixels' centres, full-resolution coordinates

  // The region's pixel farthest from `from`: where an arm reaching from a shoulder there ends
  // (a bare forearm is of the hands' class too, so the region's far end, not its centre, is the
  // hand).
  Eigen::Vector2d farthest_from(const Eigen::Vector2d& from) const;
};

// The 4-connected regions of class `cls` in `cues` with at least `min_area` working pixels,
// largest first, at most `max_blobs`.
std::vector<HandBlob> hand_blobs(const FrameCues& cues, std::uint8_t cls, int min_area,
                                 int max_blobs);

}  // namespace simcap::tracker::gomez
