#include "tracker/triangulate/unseen_keypoints.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "tracker/triangulate/reference_body.h"

namespace simcap::tracker {
namespace {

using Frames = std::vector<std::vector<std::optional<Eigen::Vector3d>>>;

TEST(UnseenKeypoints, FollowTheBodysSimilarityFromTheReference) {
  const KeypointLayout& layout = keypoint_layout(KeypointLayoutId::coco17);
  const auto reference = reference_keypoints(layout);
  const int elbow = layout.index("right_elbow"), knee = layout.index("left_knee");
  // Two frames of the reference body turned, moved and scaled by 1.1; the right elbow never
  // known, the left knee known in frame 1 only.
  const Eigen::AngleAxisd turn[] = {
      Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitY()),
      Eigen::AngleAxisd(-1.2, Eigen::Vector3d(0.1, 1, 0).normalized())};
  const Eigen::Vector3d shift[] = {{0.5, 0, -1}, {-2, 0.1, 0.3}};
  Frames frames(2, std::vector<std::optional<Eigen::Vector3d>>(layout.size()));
  for (int f = 0; f < 2; ++f) {
    for (int k = 0; k < layout.size(); ++k) {
      ASSERT_TRUE(reference[k]) << layout.keypoints[k].name;
      if (k == elbow || (k == knee && f == 0)) continue;
      frames[f][k] = Eigen::Vector3d(1.1 * (turn[f] * *reference[k]) + shift[f]);
    }
  }
  EXPECT_EQ(place_unseen_keypoints(frames, layout), std::vector<int>{elbow});
  for (int f = 0; f < 2; ++f) {
    ASSERT_TRUE(frames[f][elbow]);
    EXPECT_LT((*frames[f][elbow] - (1.1 * (turn[f] * *reference[elbow]) + shift[f])).norm(), 1e-9);
  }
  EXPECT_FALSE(frames[0][knee]) << "a keypoint seen in some frame is the gap filler's";
}

TEST(UnseenKeypoints, NeedThreeKnownKeypointsInAFrame) {
  const KeypointLayout& layout = keypoint_layout(KeypointLayoutId::coco17);
  const auto reference = reference_keypoints(layout);
  Frames frames(1, std::vector<std::optional<Eigen::Vector3d>>(layout.size()));
  frames[0][5] = reference[5];
  frames[0][6] = reference[6];
  const std::vector<int> unseen = place_unseen_keypoints(frames, layout);
  EXPECT_EQ(unseen.size(), 15u);
  for (const int k : unseen) EXPECT_FALSE(frames[0][k]);
}

}  // namespace
}  // namespace simcap::tracker
