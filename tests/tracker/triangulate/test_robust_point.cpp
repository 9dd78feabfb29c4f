// The triangulation of one keypoint against independent references: OpenCV's
// cv::undistortPoints + cv::triangulatePoints for the weighted DLT, exact points for the
// exclusion of a camera that is off by 80 px.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <random>

#include "rig.h"
#include "tracker/common/triangulation.h"
#include "tracker/triangulate/robust_point.h"

namespace simcap::tracker {
namespace {

using testing::camera_ring;

// cv::undistortPoints: normalized coordinates of a pixel with OpenCV's own lens model.
cv::Mat normalized_by_opencv(const Camera& c, const Eigen::Vector2d& pixel) {
  cv::Mat k, d;
  cv::eigen2cv(c.K, k);
  cv::eigen2cv(Eigen::VectorXd(c.dist), d);
  std::vector<cv::Point2d> in{{pixel.x(), pixel.y()}}, out;
  cv::undistortPoints(in, out, k, d);
  return cv::Mat(cv::Point2d(out[0])).clone();
}

cv::Mat extrinsics(const Camera& c) {
  Eigen::Matrix<double, 3, 4> rt;
  rt << c.R, c.t;
  cv::Mat p;
  cv::eigen2cv(rt, p);
  return p;
}

TEST(Triangulate, TwoDistortedViewsAgreeWithOpenCv) {
  const auto cams = camera_ring(2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.6, 0.6);
  std::normal_distribution<double> noise(0.0, 2.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::Vector3d x(u(rng), 1.0 + u(rng), u(rng));
    std::vector<PixelObservation> exact, noisy;
    for (const Camera& c : cams) {
      exact.push_back({&c, *c.project(x)});
      noisy.push_back({&c, exact.back().pixel + Eigen::Vector2d(noise(rng), noise(rng))});
    }
    const auto back = triangulate(exact);
    ASSERT_TRUE(back);
    EXPECT_LT((*back - x).norm(), 1e-9) << "trial " << trial;
    // With noise the algebraic solution is not the truth; OpenCV solves the same DLT on the
    // same normalized coordinates.
    cv::Mat h;
    cv::triangulatePoints(extrinsics(cams[0]), extrinsics(cams[1]),
                          normalized_by_opencv(cams[0], noisy[0].pixel),
                          normalized_by_opencv(cams[1], noisy[1].pixel), h);
    const Eigen::Vector3d theirs(h.at<double>(0), h.at<double>(1), h.at<double>(2));
    const auto mine = triangulate(noisy);
    ASSERT_TRUE(mine);
    EXPECT_LT((*mine - theirs / h.at<double>(3)).norm(), 1e-9) << "trial " << trial;
  }
}

TEST(Triangulate, WeightsScaleEachViewsRows) {
  const auto cams = camera_ring(3);
  const Eigen::Vector3d x(0.2, 1.1, -0.1);
  std::vector<PixelObservation> views;
  for (const Camera& c : cams) views.push_back({&c, *c.project(x)});
  views[2].pixel += Eigen::Vector2d(30, -20);
  // A zero weight removes the wrong view: the two exact ones give the point back.
  views[2].weight = 0.0;
  EXPECT_LT((*triangulate(views) - x).norm(), 1e-9);
  // A small weight pulls less than a full one.
  views[2].weight = 0.1;
  const double light = (*triangulate(views) - x).norm();
  views[2].weight = 1.0;
  const double full = (*triangulate(views) - x).norm();
  EXPECT_GT(light, 1e-6);
  EXPECT_LT(light, 0.5 * full);
  EXPECT_FALSE(triangulate(std::vector<PixelObservation>{views[0]}));
}

TEST(TriangulateRobust, ExcludesACameraOff80Pixels) {
  const auto cams = camera_ring(4);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.6, 0.6), angle(0, 6.283185307);
  for (int trial = 0; trial < 40; ++trial) {
    const Eigen::Vector3d x(u(rng), 1.0 + u(rng), u(rng));
    KeypointViews views;
    for (int c = 0; c < 4; ++c) views.push_back({c, *cams[c].project(x), 0.9});
    const int wrong = trial % 4;
    const double a = angle(rng);
    views[wrong].pixel += 80.0 * Eigen::Vector2d(std::cos(a), std::sin(a));
    const auto p = triangulate_robust(views, cams);
    ASSERT_TRUE(p) << "trial " << trial;
    EXPECT_LT((p->position - x).norm(), 1e-9) << "trial " << trial;
    EXPECT_EQ(p->excluded, 1);
    EXPECT_EQ(p->views, 0b1111u & ~(1u << wrong));
    EXPECT_LT(p->max_error_px, 1e-6);
  }
}

TEST(TriangulateRobust, KeepsAgreeingViewsAndRefusesWhatCannotAgree) {
  const auto cams = camera_ring(4);
  const Eigen::Vector3d x(0.1, 0.9, 0.3);
  KeypointViews views;
  for (int c = 0; c < 4; ++c) views.push_back({c, *cams[c].project(x) + Eigen::Vector2d(1, -1), 1});
  const auto p = triangulate_robust(views, cams);
  ASSERT_TRUE(p);
  EXPECT_EQ(p->excluded, 0);
  EXPECT_EQ(p->views, 0b1111u);
  EXPECT_LT((p->position - x).norm(), 0.01);
  // Two views that disagree by far more than the threshold: no point rather than a wrong one.
  KeypointViews two = {{0, *cams[0].project(x), 1},
                       {1, *cams[1].project(x) + Eigen::Vector2d(0, 90), 1}};
  EXPECT_FALSE(triangulate_robust(two, cams));
  // Unconfident observations are not used.
  two[1] = {1, *cams[1].project(x), 0.05};
  EXPECT_FALSE(triangulate_robust(two, cams));
}

}  // namespace
}  // namespace simcap::tracker
