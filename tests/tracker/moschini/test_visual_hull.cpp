#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/core.hpp>

#include "core/error.h"
#include "core/rig.h"
#include "tests/tracker/moschini/sphere_silhouette.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {
namespace {

using testing::sphere_silhouette;

// Cameras around and above a target at three elevations, with lens distortion.
std::vector<Camera> dome_rig(const Eigen::Vector3d& target) {
  const ImageSpec spec{200, 160, 0.9};
  std::vector<Camera> cams;
  for (const auto& [count, height, offset] :
       {std::tuple{5, 0.3, 0.0}, std::tuple{5, 2.0, 0.6}, std::tuple{3, 3.5, 0.2}}) {
    for (const Camera& c : ring_rig(count, target, 2.5, height, spec)) {
      Camera cam = c;
      const double a = offset;
      const Eigen::Vector3d eye = cam.centre() - target;
      const Eigen::Vector3d turned(eye.x() * std::cos(a) + eye.z() * std::sin(a), eye.y(),
                                   -eye.x() * std::sin(a) + eye.z() * std::cos(a));
      cam = Camera::look_at(camera_name(static_cast<int>(cams.size())), spec.width, spec.height,
                            spec.hfov_rad, target + turned, target);
      cam.dist << -0.08, 0.01, 0.0005, -0.0003, 0.0;
      cams.push_back(cam);
    }
  }
  return cams;
}

TEST(VisualHull, HullOfASphereContainsItAndStaysClose) {
  const Eigen::Vector3d centre(0.1, 1.0, -0.05);
  const double radius = 0.25, voxel = 0.02;
  const std::vector<Camera> cams = dome_rig(centre);
  std::vector<cv::Mat> silhouettes;
  for (const Camera& c : cams) silhouettes.push_back(sphere_silhouette(c, centre, radius));
  HullOptions options;
  options.volume =
      Eigen::AlignedBox3d(Eigen::Vector3d(-0.6, 0.3, -0.6), Eigen::Vector3d(0.6, 1.7, 0.6));
  options.voxel_m = voxel;
  options.min_views = static_cast<int>(cams.size());
  const VisualHull hull(cams, options);
  Occupancy occ;
  hull.carve(silhouettes, occ);
  ASSERT_GT(occ.count, 0);
  const VoxelGrid& g = hull.grid();
  int inside_missing = 0, far_outside = 0;
  for (int z = 0; z < g.dims.z(); ++z) {
    for (int y = 0; y < g.dims.y(); ++y) {
      for (int x = 0; x < g.dims.x(); ++x) {
        const Eigen::Vector3i v(x, y, z);
        const double d = (g.center(v) - centre).norm();
        // Pixel rounding moves the test point by under a pixel (< 1 cm here): one voxel of slack.
        if (d < radius - voxel && !occ.occupied(v)) ++inside_missing;
        if (d > radius + 2 * voxel && occ.occupied(v)) ++far_outside;
      }
    }
  }
  EXPECT_EQ(inside_missing, 0);
  EXPECT_EQ(far_outside, 0);
  const double sphere_voxels = 4.0 / 3 * M_PI * std::pow(radius / voxel, 3);
  EXPECT_GT(occ.count, 0.95 * sphere_voxels);
  EXPECT_LT(occ.count, 1.6 * sphere_voxels);
}

// The pruned carving equals the definition applied voxel by voxel with Camera::project.
TEST(VisualHull, CoarseToFineEqualsTheDirectDefinition) {
  const Eigen::Vector3d centre(0.0, 1.0, 0.0);
  std::vector<Camera> cams = ring_rig(4, centre, 2.0, 2.2, {160, 120, 1.0});
  for (Camera& c : cams) c.dist << 0.05, -0.01, 0.001, 0.0, 0.0;
  std::vector<cv::Mat> silhouettes;
  cv::RNG rng(3);
  for (const Camera& c : cams) {
    cv::Mat m = sphere_silhouette(c, centre + Eigen::Vector3d(0.1, 0, 0), 0.2) |
                sphere_silhouette(c, centre + Eigen::Vector3d(-0.2, 0.3, 0.1), 0.12);
    for (int i = 0; i < 200; ++i)
      m.at<std::uint8_t>(rng.uniform(0, m.rows), rng.uniform(0, m.cols)) = 255;
    silhouettes.push_back(m);
  }
  HullOptions options;
  options.volume =
      Eigen::AlignedBox3d(Eigen::Vector3d(-1.3, 0.0, -1.3), Eigen::Vector3d(1.3, 2.0, 1.3));
  options.voxel_m = 0.03;
  for (int min_views : {3, 4}) {
    options.min_views = min_views;
    const VisualHull hull(cams, options);
    Occupancy occ;
    hull.carve(silhouettes, occ);
    const VoxelGrid& g = hull.grid();
    int mismatches = 0, occupied = 0;
    for (int z = 0; z < g.dims.z(); ++z) {
      for (int y = 0; y < g.dims.y(); ++y) {
        for (int x = 0; x < g.dims.x(); ++x) {
          const Eigen::Vector3i v(x, y, z);
          int views = 0;
          bool inside = true;
          for (size_t c = 0; c < cams.size(); ++c) {
            const auto px = cams[c].project(g.center(v));
            if (!px) continue;
            const int u = static_cast<int>(std::floor(px->x() + 0.5));
            const int w = static_cast<int>(std::floor(px->y() + 0.5));
            if (u < 0 || w < 0 || u >= cams[c].width || w >= cams[c].height) continue;
            ++views;
            inside = inside && silhouettes[c].at<std::uint8_t>(w, u) != 0;
          }
          const bool expected = views >= min_views && inside;
          occupied += expected;
          mismatches += expected != occ.occupied(v);
        }
      }
    }
    EXPECT_GT(occupied, 100);
    EXPECT_EQ(mismatches, 0) << "min_views " << min_views;
    EXPECT_EQ(occ.count, occupied);
  }
}

TEST(VisualHull, RejectsBadInput) {
  const std::vector<Camera> cams = ring_rig(3, {0, 1, 0}, 2.0, 2.0, {64, 48, 1.0});
  HullOptions options;
  options.voxel_m = 0.0;
  EXPECT_THROW(VisualHull(cams, options), Error);
  options.voxel_m = 0.05;
  const VisualHull hull(cams, options);
  Occupancy occ;
  EXPECT_THROW(hull.carve({cv::Mat(48, 64, CV_8UC1, cv::Scalar(0))}, occ), Error);
  EXPECT_THROW(hull.carve(std::vector<cv::Mat>(3, cv::Mat(10, 10, CV_8UC1, cv::Scalar(0))), occ),
               Error);
}

}  // namespace
}  // namespace simcap::tracker
