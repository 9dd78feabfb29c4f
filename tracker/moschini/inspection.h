// One frame of Moschini's tracker laid open for a look: per camera, the image with the
// silhouette's edge, the centerline points, the fitted capsules' outlines and the sticks drawn
// on it; the visual hull's voxels as a point list.
#pragma once

#include <filesystem>

#include "tracker/common/dataset.h"
#include "tracker/moschini/moschini_tracker.h"
#include "tracker/moschini/perception.h"

namespace simcap::tracker {

// Writes into `dir` (created): camNN.png per camera (the frame's RGB image, or its mask when the
// dataset has none, cropped to the person and enlarged; silhouette edge yellow, centerline points
// magenta, capsule outlines green where inside the silhouette and red where outside, sticks blue,
// estimated joints white) and hull.csv (x,y,z of every occupied voxel's centre, metres). Each file
// is written atomically.
void write_inspection(const std::filesystem::path& dir, const Dataset& dataset,
                      const Observation& obs, const MoschiniTracker& tracker,
                      const StickPose& pose);

}  // namespace simcap::tracker
