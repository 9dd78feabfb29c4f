// Centerline points of a voxel volume by slicing (Moschini §3.2): the centroid of every
// connected component of every axis-parallel slice, swept along X, Y and Z.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {

struct SkeletonOptions {
  bool sweep_x = true, sweep_y = true, sweep_z = true;
  // Blobs with fewer voxels are noise (a 2 cm hull gives a forearm ~10 voxels in cross-section).
  int min_blob_voxels = 3;
  // A blob whose principal standard deviations differ by more than this ratio is cut lengthwise
  // or joins several parts (the T-pose arm slice, §3.2): its centroid is dropped.
  double max_elongation = 2.0;
  // In the vertical slices (the X and Z sweeps) an upright body is cut
  // lengthwise; only limbs lying across such a slice (a raised arm, a lifted thigh) give small
  // cross-sections there. Larger blobs in X and Z slices are lengthwise cuts or grazes of the
  // body surface whose centroids lie off every axis: dropped. Area in m² (0: no limit).
  double max_vertical_blob_m2 = 0.02;
  // A non-convex blob's centroid can fall outside it, off every centerline (§3.2): dropped.
  bool drop_centroids_outside = true;
};

struct CenterlinePoint {
  Eigen::Vector3d position;
  int axis;           // sweep axis: 0 = X, 1 = Y, 2 = Z
  int voxels;         // blob area
  double elongation;  // ratio of its principal standard deviations (>= 1)
};

// Points in sweep order (X, then Y, then Z; slices ascending; blobs in label order).
std::vector<CenterlinePoint> centerline(const Occupancy& occupancy, const SkeletonOptions& options);

}  // namespace simcap::tracker
