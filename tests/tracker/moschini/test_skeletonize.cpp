#include <gtest/gtest.h>

#include "tracker/moschini/skeletonize.h"

namespace simcap::tracker {
namespace {

// An occupancy box of `size` voxels (1 cm) whose cells `inside` decides.
template <typename Inside>
Occupancy make_occupancy(const Eigen::Vector3i& size, Inside inside) {
  Occupancy occ;
  occ.grid.origin = Eigen::Vector3d(-1, 0, -1);
  occ.grid.voxel = 0.01;
  occ.grid.dims = Eigen::Vector3i(200, 200, 200);
  occ.lo = Eigen::Vector3i(10, 10, 10);
  occ.size = size;
  occ.cells.assign(static_cast<size_t>(size.prod()), 0);
  for (int y = 0; y < size.y(); ++y)
    for (int z = 0; z < size.z(); ++z)
      for (int x = 0; x < size.x(); ++x)
        if (inside(x, y, z)) {
          occ.cells[(static_cast<size_t>(y) * size.z() + z) * size.x() + x] = 1;
          ++occ.count;
        }
  return occ;
}

TEST(Skeletonize, CentroidsOfAnUprightCylinderLieOnItsAxis) {
  // Radius 6 voxels around (x, z) = (15.5, 12.5), 60 voxels tall.
  const Occupancy occ = make_occupancy({32, 60, 26}, [](int x, int, int z) {
    return (x - 15.5) * (x - 15.5) + (z - 12.5) * (z - 12.5) <= 36;
  });
  SkeletonOptions opt;
  opt.sweep_x = opt.sweep_z = false;
  const auto points = centerline(occ, opt);
  ASSERT_EQ(points.size(), 60u);
  const Eigen::Vector3d axis = occ.grid.origin + occ.grid.voxel * Eigen::Vector3d(25.5, 0, 22.5);
  for (const auto& p : points) {
    EXPECT_EQ(p.axis, 1);
    EXPECT_NEAR(p.position.x(), axis.x(), 1e-9);
    EXPECT_NEAR(p.position.z(), axis.z(), 1e-9);
    EXPECT_LT(p.elongation, 1.1);
  }
}

TEST(Skeletonize, ElongatedAndNonConvexBlobsAreDropped) {
  // One horizontal slab per Y slice: a 40 x 4 bar (elongated), and in the upper half an L-shape
  // whose centroid falls outside it.
  const Occupancy bar = make_occupancy(
      {44, 10, 10}, [](int x, int, int z) { return x >= 2 && x < 42 && z >= 3 && z < 7; });
  SkeletonOptions opt;
  opt.sweep_x = opt.sweep_z = false;
  EXPECT_TRUE(centerline(bar, opt).empty());
  opt.max_elongation = 100;
  EXPECT_EQ(centerline(bar, opt).size(), 10u);
  const Occupancy ell = make_occupancy(
      {30, 4, 30}, [](int x, int, int z) { return (x < 4 && z < 30) || (z < 4 && x < 30); });
  EXPECT_TRUE(centerline(ell, opt).empty());
  opt.drop_centroids_outside = false;
  EXPECT_EQ(centerline(ell, opt).size(), 4u);
}

TEST(Skeletonize, TheXSweepFindsAHorizontalArm) {
  // A bar along X (an arm held out sideways): horizontal slices cut it lengthwise, X slices across.
  const Occupancy arm = make_occupancy({50, 8, 8}, [](int, int y, int z) {
    return (y - 3.5) * (y - 3.5) + (z - 3.5) * (z - 3.5) <= 9;
  });
  SkeletonOptions opt;
  const auto points = centerline(arm, opt);
  int across = 0;
  for (const auto& p : points) {
    if (p.axis != 0) continue;
    ++across;
    EXPECT_NEAR(p.position.y(), arm.grid.origin.y() + arm.grid.voxel * (arm.lo.y() + 3.5), 1e-9);
  }
  EXPECT_EQ(across, 50);
}

}  // namespace
}  // namespace simcap::tracker
