#include <gtest/gtest.h>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tracker/moschini/occlusion_map.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {
namespace {

using testing::camera_ring;
using testing::ring_camera;

// The capsule body on the walking pose seen by four ring cameras; in camera 0 a pillar (a
// vertical band of another colour on its plate) stands in front of the left forearm.
struct PillarScene {
  StickModel model{testing::capsule_body(), JointSet::urdf};
  BodySurface surface = testing::capsule_surface();
  StickPose pose = testing::walking_pose();
  std::vector<double> azimuths = camera_ring(4);
  std::vector<Camera> cameras;
  std::vector<cv::Mat> masks, seen, plates;
  cv::Rect pillar;

  PillarScene() {
    for (const double a : azimuths) cameras.push_back(ring_camera(pose, a));
    masks = testing::silhouette_masks(model, surface, pose, azimuths);
    const StickGeometry g = model.geometry(pose);
    const Eigen::Vector3d mid = 0.5 * (g.proximal[kLForearm] + g.distal[kLForearm]);
    const int u = static_cast<int>(cameras[0].project(mid)->x());
    pillar = cv::Rect(u - 24, 0, 48, cameras[0].height);
    for (size_t c = 0; c < cameras.size(); ++c) {
      plates.emplace_back(cameras[c].height, cameras[c].width, CV_8UC3, cv::Scalar(150, 150, 150));
      seen.push_back(masks[c].clone());
    }
    plates[0](pillar).setTo(cv::Scalar(60, 90, 120));
    seen[0](pillar).setTo(0);
  }

  // How many of nine points along the left forearm's axis are in the hull of `silhouettes`.
  int forearm_in_hull(const std::vector<cv::Mat>& silhouettes) const {
    HullOptions options;
    options.volume = {pose.t0 - Eigen::Vector3d(1.2, 1.2, 1.2),
                      pose.t0 + Eigen::Vector3d(1.2, 1.0, 1.2)};
    Occupancy hull;
    VisualHull(cameras, options).carve(silhouettes, hull);
    const StickGeometry g = model.geometry(pose);
    int in = 0;
    for (int k = 1; k <= 9; ++k) {
      const Eigen::Vector3d x =
          g.proximal[kLForearm] + k / 10.0 * (g.distal[kLForearm] - g.proximal[kLForearm]);
      in += hull.occupied_near(x, 0) ? 1 : 0;
    }
    return in;
  }
};

TEST(OcclusionMap, AForearmHiddenByAPillarInOneCameraKeepsItsVoxels) {
  const PillarScene s;
  ASSERT_EQ(s.forearm_in_hull(s.masks), 9);
  // Carved with the occluded silhouette, the forearm is gone: the case to mend.
  ASSERT_LE(s.forearm_in_hull(s.seen), 2);

  OcclusionMap map(s.cameras, s.plates);
  map.observe(place(s.surface, s.model.geometry(s.pose)), s.seen);
  std::vector<cv::Mat> widened;
  for (size_t c = 0; c < s.cameras.size(); ++c) widened.push_back(map.widen(c, s.seen[c]));
  EXPECT_EQ(s.forearm_in_hull(widened), 9);

  // What is blocked is the pillar, whole, with its outline (the plate's edge cells, 4 px), and
  // only in the camera it stands before.
  const cv::Mat blocked = map.blocked(0);
  EXPECT_EQ(cv::countNonZero(blocked(s.pillar)), s.pillar.area());
  const cv::Rect outline(s.pillar.x - 4, 0, s.pillar.width + 8, s.pillar.height);
  EXPECT_EQ(cv::countNonZero(blocked), cv::countNonZero(blocked(outline)));
  for (size_t c = 1; c < s.cameras.size(); ++c) {
    EXPECT_EQ(cv::countNonZero(map.blocked(c)), 0) << c;
    EXPECT_EQ(widened[c].data, s.seen[c].data) << c;
  }
}

TEST(OcclusionMap, APartSeenAtTheDepthItWasHiddenAtClearsTheRegion) {
  const PillarScene s;
  OcclusionMap map(s.cameras, s.plates);
  const PlacedSurface body = place(s.surface, s.model.geometry(s.pose));
  map.observe(body, s.seen);
  ASSERT_GT(cv::countNonZero(map.blocked(0)), 0);
  // The same forearm, at the same depth, now seen on the band: the band hides nothing.
  map.observe(body, s.masks);
  EXPECT_EQ(cv::countNonZero(map.blocked(0)), 0);
}

TEST(OcclusionMap, NothingIsBlockedWhenEveryCameraSeesTheBody) {
  const PillarScene s;
  OcclusionMap map(s.cameras, s.plates);
  map.observe(place(s.surface, s.model.geometry(s.pose)), s.masks);
  for (size_t c = 0; c < s.cameras.size(); ++c) {
    EXPECT_EQ(cv::countNonZero(map.blocked(c)), 0) << c;
    EXPECT_EQ(map.widen(c, s.masks[c]).data, s.masks[c].data) << c;
  }
}

// Images smaller than the colour classes' cells (a 1x1 or 8x6 camera) give a plate of one region
// instead of asking k-means for more clusters than cells.
TEST(OcclusionMap, ATinyPlateIsOneRegion) {
  const PillarScene s;
  for (const cv::Size size : {cv::Size(1, 1), cv::Size(8, 6), cv::Size(13, 3)}) {
    std::vector<Camera> cameras = s.cameras;
    std::vector<cv::Mat> plates, masks;
    for (Camera& c : cameras) {
      c.width = size.width;
      c.height = size.height;
      plates.emplace_back(size, CV_8UC3, cv::Scalar(150, 150, 150));
      masks.emplace_back(size, CV_8UC1, cv::Scalar(255));
    }
    OcclusionMap map(cameras, plates);
    map.observe(place(s.surface, s.model.geometry(s.pose)), masks);
    EXPECT_EQ(cv::countNonZero(map.blocked(0)), 0) << size;
  }
}

}  // namespace
}  // namespace simcap::tracker
