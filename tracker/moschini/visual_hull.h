// Shape from silhouette (Moschini §3.1) on a voxel grid: a voxel is occupied iff it projects
// inside the silhouette of every camera that sees it. Voxel-to-pixel tables are built once.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker {

struct VoxelGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // centre of voxel (0, 0, 0)
  double voxel = 0.02;
  Eigen::Vector3i dims = Eigen::Vector3i::Zero();  // voxels along x, y, z

  Eigen::Vector3d center(const Eigen::Vector3i& v) const {
    return origin + voxel * v.cast<double>();
  }
  // Index of the voxel containing `world` (may lie outside dims).
  Eigen::Vector3i index(const Eigen::Vector3d& world) const;
};

struct HullOptions {
  Eigen::AlignedBox3d volume{Eigen::Vector3d(-1.5, 0.0, -1.5), Eigen::Vector3d(1.5, 2.1, 1.5)};
  double voxel_m = 0.02;
  // A voxel seen by fewer cameras is empty (one or two silhouettes give long cones, not a
  // body). 0 picks all cameras but one, and at least two.
  int min_views = 0;
};

// The occupied voxels of one frame, stored densely inside their bounding box.
struct Occupancy {
  VoxelGrid grid;
  Eigen::Vector3i lo = Eigen::Vector3i::Zero();    // grid index of the box's first voxel
  Eigen::Vector3i size = Eigen::Vector3i::Zero();  // box extent in voxels (x, y, z)
  std::vector<std::uint8_t> cells;  // 1 = occupied; (y * size.z + z) * size.x + x, box-relative
  int count = 0;

  // v in grid indices. (Inline: the fitting asks it for every voxel it searches.)
  bool occupied(const Eigen::Vector3i& v) const {
    const Eigen::Vector3i r = v - lo;
    if ((r.array() < 0).any() || (r.array() >= size.array()).any()) return false;
    return cells[(static_cast<size_t>(r.y()) * size.z() + r.z()) * size.x() + r.x()] != 0;
  }
  // True when a voxel within `radius` voxels (Chebyshev) of the one containing `world` is set.
  bool occupied_near(const Eigen::Vector3d& world, int radius) const;
};

class VisualHull {
 public:
  VisualHull(std::vector<Camera> cameras, const HullOptions& options);
  const VoxelGrid& grid() const { return grid_; }
  const std::vector<Camera>& cameras() const { return cameras_; }

  // silhouettes[c]: CV_8UC1 at camera c's size, nonzero = foreground. Thread-safe.
  void carve(const std::vector<cv::Mat>& silhouettes, Occupancy& out) const;

 private:
  // Groups of 4x4x4 blocks, then blocks of 4x4x4 voxels, are tested first against each
  // camera's silhouette with a summed area table over the pixel box they project to; only
  // blocks that survive every camera are tested voxel by voxel.
  static constexpr int kBlock = 4;
  static constexpr int kBlockVoxels = kBlock * kBlock * kBlock;
  static constexpr int kGroup = 4;  // blocks per group along each axis
  struct PixelBox {
    std::int16_t u0, v0, u1, v1;  // inclusive; u0 > u1 when the camera does not constrain
  };
  std::vector<Camera> cameras_;
  VoxelGrid grid_;
  Eigen::Vector3i blocks_ = Eigen::Vector3i::Zero();
  Eigen::Vector3i groups_ = Eigen::Vector3i::Zero();
  int min_views_ = 0;
  std::vector<std::uint8_t> block_live_;            // some voxel of the block has enough views
  std::vector<std::uint8_t> group_live_;            // some block of the group is live
  std::vector<std::vector<std::uint32_t>> lut_;     // per camera, per voxel (block-major)
  std::vector<std::vector<PixelBox>> boxes_;        // per camera, per block
  std::vector<std::vector<PixelBox>> group_boxes_;  // per camera, per group (union of its blocks')
};

}  // namespace simcap::tracker
