// SilhouetteView against a brute-force nearest-pixel search, and the rim residuals of the
// refinement pulling a capsule that overhangs the silhouettes back inside.
#include <gtest/gtest.h>

#include <numbers>
#include <opencv2/imgproc.hpp>
#include <random>

#include "tests/tracker/moschini/ray_rig.h"
#include "tests/tracker/moschini/refine_test_support.h"
#include "tracker/moschini/pose_refiner.h"
#include "tracker/moschini/silhouette_view.h"

namespace simcap::tracker {
namespace {

TEST(SilhouetteView, FindsTheNearestSilhouettePixel) {
  cv::Mat mask = cv::Mat::zeros(120, 160, CV_8U);
  cv::ellipse(mask, {70, 60}, {25, 40}, 20, 0, 360, 255, cv::FILLED);
  cv::rectangle(mask, {100, 20}, {110, 90}, 255, cv::FILLED);
  const Camera cam = Camera::look_at("c", 160, 120, 1.0, {0, 1, 3}, {0, 1, 0});
  const SilhouetteView view(cam, mask, 20);
  ASSERT_FALSE(view.empty());
  std::vector<cv::Point> on;
  cv::findNonZero(mask, on);
  std::mt19937 rng(3);
  for (int trial = 0; trial < 400; ++trial) {
    const int u = static_cast<int>(rng() % 160), v = static_cast<int>(rng() % 120);
    double best = 1e9;
    for (const cv::Point& p : on) best = std::min(best, std::hypot(p.x - u, p.y - v));
    const Eigen::Vector2i n = view.nearest(u, v);
    ASSERT_NE(mask.at<std::uint8_t>(n.y(), n.x()), 0) << u << "," << v;
    EXPECT_EQ(view.inside(u, v), mask.at<std::uint8_t>(v, u) != 0) << u << "," << v;
    // Within the map, a 5x5-mask distance transform is within a few percent of exact; beyond
    // its margin the box edge stands in, which may be up to the margin farther.
    const bool in_box = u >= 25 && u <= 130 && v >= 0 && v <= 119;
    const double found = std::hypot(n.x() - u, n.y() - v);
    EXPECT_LE(found, in_box ? best * 1.05 + 1.0 : best + 20.0) << u << "," << v;
  }
  EXPECT_TRUE(SilhouetteView(cam, cv::Mat::zeros(120, 160, CV_8U)).empty());
}

TEST(PoseRefiner, RimResidualsPullAnOverhangingArmInside) {
  const StickModel model(testing::capsule_body(), JointSet::urdf);
  StickPose truth;
  truth.t0 = {0, 1.1, 0};
  truth.theta[kLShoulder1] = 0.6;
  truth.theta[kLElbow] = -0.5;
  const std::vector<double> azimuths = testing::camera_ring(4);
  std::vector<Camera> cams;
  for (const double a : azimuths) cams.push_back(testing::ring_camera(truth, a));
  const auto masks = testing::silhouette_masks(model, testing::capsule_surface(), truth, azimuths);
  std::vector<SilhouetteView> views;
  for (size_t c = 0; c < cams.size(); ++c) views.emplace_back(cams[c], masks[c]);
  IcpTargets targets;
  targets.views = &views;
  const PoseRefiner refiner(model, testing::capsule_surface(),
                            testing::converging_without_priors());
  // Lifted 0.4 rad too far: the arm sticks out of every silhouette.
  StickPose pose = truth;
  pose.theta[kLShoulder1] = 1.0;
  const auto hand = [&](const StickPose& p) {
    return model.reference_points(model.geometry(p))[kLHandTip];
  };
  ASSERT_GT((hand(pose) - hand(truth)).norm(), 0.2);
  const double before = refiner.cost(targets, pose);
  ASSERT_GT(before, 0);
  refiner.refine(targets, pose);
  EXPECT_LT(refiner.cost(targets, pose), 0.05 * before);
  EXPECT_LT((hand(pose) - hand(truth)).norm(), 0.05);
}

}  // namespace
}  // namespace simcap::tracker
