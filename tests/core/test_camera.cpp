// The camera model against OpenCV's own projectPoints, and its inverse against itself.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <random>

#include "core/camera.h"
#include "core/error.h"
#include "core/rig.h"

namespace simcap {
namespace {

Camera random_camera(std::mt19937& rng, bool strong_distortion) {
  std::uniform_real_distribution<double> u(-1, 1);
  const Eigen::Vector3d eye(3 * u(rng), 1.5 + u(rng), 3 * u(rng));
  Camera c = Camera::look_at("cam", 640, 480, 0.9 + 0.3 * u(rng), eye,
                             Eigen::Vector3d(0.3 * u(rng), 1.0, 0.3 * u(rng)));
  c.K(1, 1) *= 1.0 + 0.05 * u(rng);
  c.K(0, 2) += 10 * u(rng);
  // "Strong" is a wide-angle barrel lens (k1 < 0, k2 > 0) whose distortion stays monotonic
  // over the image, as real calibrated lenses do; "mild" a typical machine-vision lens.
  if (strong_distortion) {
    c.dist << -0.28 + 0.04 * u(rng), 0.08 + 0.03 * u(rng), 0.002 * u(rng), 0.002 * u(rng),
        -0.01 + 0.005 * u(rng);
  } else {
    c.dist << -0.06 + 0.02 * u(rng), 0.02 * u(rng), 0.001 * u(rng), 0.001 * u(rng), 0.0;
  }
  return c;
}

std::vector<cv::Point2d> opencv_project(const Camera& c, const std::vector<Eigen::Vector3d>& pts) {
  std::vector<cv::Point3d> obj;
  for (const auto& p : pts) obj.emplace_back(p.x(), p.y(), p.z());
  cv::Mat R, K, dist, rvec, tvec;
  cv::eigen2cv(c.R, R);
  cv::eigen2cv(c.K, K);
  cv::eigen2cv(Eigen::VectorXd(c.dist), dist);
  cv::eigen2cv(Eigen::VectorXd(c.t), tvec);
  cv::Rodrigues(R, rvec);
  std::vector<cv::Point2d> out;
  cv::projectPoints(obj, rvec, tvec, K, dist, out);
  return out;
}

// True when the radial polynomial is still increasing at the image corners, i.e. every pixel has
// an undistorted preimage (a real calibration never extends past the fold).
bool lens_covers_image(const Camera& c) {
  const double k1 = c.dist[0], k2 = c.dist[1], k3 = c.dist[2 + 2];
  const double corner = std::hypot(std::max(c.K(0, 2), c.width - c.K(0, 2)) / c.K(0, 0),
                                   std::max(c.K(1, 2), c.height - c.K(1, 2)) / c.K(1, 1));
  for (double r = 0; r < 3; r += 1e-3) {
    const double r2 = r * r;
    if (1 + 3 * k1 * r2 + 5 * k2 * r2 * r2 + 7 * k3 * r2 * r2 * r2 <= 0) {
      return r * (1 + k1 * r2 + k2 * r2 * r2 + k3 * r2 * r2 * r2) > 1.05 * corner;
    }
  }
  return true;
}

class CameraVsOpenCV : public ::testing::TestWithParam<bool> {};

TEST_P(CameraVsOpenCV, ProjectAgreesWithProjectPoints) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const Camera c = random_camera(rng, GetParam());
    std::vector<Eigen::Vector3d> pts;
    // Points inside the view so that distortion stays in its realistic, monotonic range.
    for (int i = 0; i < 200; ++i) {
      const Eigen::Vector2d px(320 + 300 * u(rng), 240 + 220 * u(rng));
      pts.push_back(c.centre() + (1.0 + 4 * std::abs(u(rng))) * c.unproject(px));
    }
    const auto ref = opencv_project(c, pts);
    for (size_t i = 0; i < pts.size(); ++i) {
      const auto px = c.project(pts[i]);
      ASSERT_TRUE(px.has_value());
      EXPECT_NEAR(px->x(), ref[i].x, 1e-6);
      EXPECT_NEAR(px->y(), ref[i].y, 1e-6);
    }
  }
}

TEST_P(CameraVsOpenCV, UnprojectRoundTripsOverTheWholeImage) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Camera c = random_camera(rng, GetParam());
    if (!lens_covers_image(c)) continue;
    double worst = 0;
    for (int v = 0; v < c.height; v += 8) {
      for (int uu = 0; uu < c.width; uu += 8) {
        const Eigen::Vector2d px(uu, v);
        const Eigen::Vector3d ray = c.unproject(px);
        EXPECT_NEAR(ray.norm(), 1.0, 1e-12);
        const auto back = c.project(c.centre() + 2.5 * ray);
        ASSERT_TRUE(back.has_value());
        worst = std::max(worst, (*back - px).norm());
      }
    }
    EXPECT_LT(worst, 1e-6) << "trial " << trial;
  }
}

INSTANTIATE_TEST_SUITE_P(Distortion, CameraVsOpenCV, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? "strong" : "mild"; });

TEST(Camera, UndistortAgreesWithOpenCV) {
  std::mt19937 rng(3);
  const Camera c = random_camera(rng, true);
  cv::Mat K, dist;
  cv::eigen2cv(c.K, K);
  cv::eigen2cv(Eigen::VectorXd(c.dist), dist);
  std::vector<cv::Point2d> px = {{10, 10}, {320, 240}, {600, 450}, {40, 400}}, out;
  cv::undistortPoints(
      px, out, K, dist, cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 200, 1e-14));
  for (size_t i = 0; i < px.size(); ++i) {
    const Eigen::Vector3d ray = c.unproject_camera({px[i].x, px[i].y});
    EXPECT_NEAR(ray.x() / ray.z(), out[i].x, 1e-6);
    EXPECT_NEAR(ray.y() / ray.z(), out[i].y, 1e-6);
  }
}

TEST(Camera, LookAtFollowsOpenCVAxes) {
  const Camera c = Camera::look_at("c", 640, 480, std::numbers::pi / 2, {0, 1, 5}, {0, 1, 0});
  EXPECT_TRUE(c.centre().isApprox(Eigen::Vector3d(0, 1, 5)));
  EXPECT_NEAR(c.R.determinant(), 1.0, 1e-12);
  // The target is straight ahead, at the principal point.
  const auto centre = c.project({0, 1, 0});
  EXPECT_NEAR(centre->x(), 319.5, 1e-9);
  EXPECT_NEAR(centre->y(), 239.5, 1e-9);
  // World up is image up (smaller v); the camera looks along -Z, so world +X is image left.
  EXPECT_LT(c.project({0, 2, 0})->y(), 239.5);
  EXPECT_FALSE(c.project({0, 1, 6}).has_value());
  EXPECT_TRUE(c.in_frustum({0, 1, 0}));
  EXPECT_FALSE(c.in_frustum({0, 1, 6}));
  EXPECT_FALSE(c.in_frustum({10, 1, 0}));
  EXPECT_NEAR(c.hfov(), std::numbers::pi / 2, 1e-12);
  EXPECT_THROW(Camera::look_at("c", 640, 480, 1.0, {0, 5, 0}, {0, 0, 0}), Error);
}

TEST(Rig, RingCamerasAllSeeTheTarget) {
  const Eigen::Vector3d target(0.5, 1.0, -0.2);
  const auto cams = ring_rig(8, target, 3.0, 2.0, ImageSpec{});
  ASSERT_EQ(cams.size(), 8u);
  EXPECT_EQ(cams[0].name, "cam00");
  EXPECT_EQ(cams[7].name, "cam07");
  for (const auto& c : cams) {
    const Eigen::Vector3d d = c.centre() - target;
    EXPECT_NEAR(std::hypot(d.x(), d.z()), 3.0, 1e-9);
    EXPECT_NEAR(c.centre().y(), 2.0, 1e-9);
    EXPECT_NEAR(c.project(target)->x(), 319.5, 1e-9);
  }
  EXPECT_GT(cams[0].centre().z(), target.z());  // first camera in front of the humanoid
  EXPECT_THROW(ring_rig(0, target, 3.0, 2.0, ImageSpec{}), Error);
}

TEST(Rig, CornerCamerasSitInsideTheRoom) {
  const auto cams = corner_rig(4.0, 5.0, 2.5, 0.1, {0, 1, 0}, ImageSpec{});
  ASSERT_EQ(cams.size(), 4u);
  for (const auto& c : cams) {
    EXPECT_NEAR(std::abs(c.centre().x()), 1.9, 1e-9);
    EXPECT_NEAR(std::abs(c.centre().z()), 2.4, 1e-9);
    EXPECT_TRUE(c.in_frustum({0, 0, 0}));
    EXPECT_TRUE(c.in_frustum({0, 1.8, 0}));
  }
  EXPECT_THROW(corner_rig(0.1, 5.0, 2.5, 0.1, {0, 1, 0}, ImageSpec{}), Error);
}

}  // namespace
}  // namespace simcap
