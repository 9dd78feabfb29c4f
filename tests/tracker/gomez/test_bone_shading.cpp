// The arm bones' shading cue against independent computations: the closed-form Lambert mean of a
// cylinder against a numeric integral, a ray-cast lit cylinder told from its depth flip, and the
// start frame's light fit recovering the light of a ray-cast ball.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <opencv2/core.hpp>

#include "tracker/gomez/bone_shading.h"
#include "tracker/gomez/light_fit.h"

namespace simcap::tracker::gomez {
namespace {

// The mean of max(0, n . l) over the visible normals, weighted by their projected width, by
// summing over the cylinder's whole circumference.
double numeric_mean(const Eigen::Vector3d& axis, const Eigen::Vector3d& to_camera,
                    const Eigen::Vector3d& l) {
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d e1 = a.unitOrthogonal(), e2 = a.cross(e1);
  const Eigen::Vector3d v = to_camera.normalized();
  double lit = 0, width = 0;
  const int steps = 20000;
  for (int k = 0; k < steps; ++k) {
    const double p = 2 * std::numbers::pi * (k + 0.5) / steps;
    const Eigen::Vector3d n = std::cos(p) * e1 + std::sin(p) * e2;
    const double w = std::max(0.0, n.dot(v));
    width += w;
    lit += w * std::max(0.0, n.dot(l));
  }
  return lit / width;
}

TEST(BoneShading, LambertMeanMatchesANumericIntegral) {
  // Lit from the camera's side, across the axis: the mean of cos^2 over the half is pi/4.
  EXPECT_NEAR(lambert_cylinder_mean({0, 1, 0}, {0, 0, -3}, {0, 0, -1}), std::numbers::pi / 4,
              1e-12);
  // Lit along the axis: no light falls on the side.
  EXPECT_NEAR(lambert_cylinder_mean({0, 1, 0}, {0, 0, -3}, {0, 1, 0}), 0.0, 1e-12);
  // Lit from behind, across the axis: none of the visible half.
  EXPECT_NEAR(lambert_cylinder_mean({0, 1, 0}, {0, 0, -3}, {0, 0, 1}), 0.0, 1e-12);
  const Eigen::Vector3d axes[] = {{0.2, 1, 0.3}, {1, 0.1, -0.5}, {-0.3, -0.8, 0.6}};
  const Eigen::Vector3d views[] = {{0.1, -0.2, -2.7}, {-0.5, 0.4, -3.0}};
  const Eigen::Vector3d lights[] = {{0.27, -0.85, -0.46}, {-0.6, 0.2, 0.77}, {0.1, 0.1, -0.99}};
  for (const auto& a : axes) {
    for (const auto& v : views) {
      for (const auto& l : lights) {
        const Eigen::Vector3d u = l.normalized();
        EXPECT_NEAR(lambert_cylinder_mean(a, v, u), numeric_mean(a, v, u), 1e-5);
      }
    }
  }
}

// The mean grey of the pixels of a cylinder (axis from `start` along `axis`, camera coordinates,
// pinhole of focal f at the origin looking along +z) ray-cast pixel by pixel and shaded
// albedo (ambient + max(0, n . l)).
double rendered_grey(const Eigen::Vector3d& start, const Eigen::Vector3d& axis, double radius,
                     const Eigen::Vector3d& l, double albedo, double ambient) {
  const double f = 500;
  const Eigen::Vector3d a = axis.normalized();
  const double length = axis.norm();
  double sum = 0;
  int count = 0;
  for (int y = -200; y <= 200; ++y) {
    for (int x = -200; x <= 200; ++x) {
      const Eigen::Vector3d d = Eigen::Vector3d(x / f, y / f, 1).normalized();
      // |q - (q . a) a| = radius with q = t d - start: a quadratic in t.
      const Eigen::Vector3d dp = d - d.dot(a) * a, sp = -start + start.dot(a) * a;
      const double A = dp.squaredNorm(), B = 2 * dp.dot(sp), C = sp.squaredNorm() - radius * radius;
      const double disc = B * B - 4 * A * C;
      if (A < 1e-12 || disc < 0) continue;
      const double t = (-B - std::sqrt(disc)) / (2 * A);
      const Eigen::Vector3d q = t * d - start;
      const double along = q.dot(a);
      if (t <= 0 || along < 0 || along > length) continue;
      const Eigen::Vector3d n = (q - along * a).normalized();
      sum += albedo * (ambient + std::max(0.0, n.dot(l)));
      ++count;
    }
  }
  return count ? sum / count : 0.0;
}

TEST(BoneShading, ALitCylinderIsToldFromItsDepthFlip) {
  // An upper arm hanging down and tilted 30 degrees towards the camera, 2.7 m away, under a light
  // from above and in front (camera coordinates: y down, z away from the camera).
  const Eigen::Vector3d l = Eigen::Vector3d(0.27, -0.85, -0.46).normalized();
  const Eigen::Vector3d shoulder(0.15, -0.2, 2.7);
  const double tilt = std::numbers::pi / 6;
  const Eigen::Vector3d axis = 0.3 * Eigen::Vector3d(0, std::cos(tilt), -std::sin(tilt));
  // Its H4 flip: the elbow on its own camera ray at the mirrored depth about the shoulder.
  const Eigen::Vector3d flipped = 0.3 * Eigen::Vector3d(0, std::cos(tilt), std::sin(tilt));
  const double albedo = 160, ambient = 0.3;
  Lighting lighting;
  lighting.to_light = l;
  lighting.albedo[1] = albedo;
  lighting.offset[1] = albedo * ambient;
  BoneSample bone;
  bone.cls = 1;
  bone.pixels = 100;
  bone.grey = rendered_grey(shoulder, axis, 0.04, l, albedo, ambient);
  bone.axis = axis;
  bone.to_camera = -(shoulder + 0.5 * axis);
  BoneSample flip = bone;
  flip.axis = flipped;
  flip.to_camera = -(shoulder + 0.5 * flipped);
  const double truth = std::abs(bone.grey - predicted_grey(bone, lighting));
  const double other = std::abs(bone.grey - predicted_grey(flip, lighting));
  EXPECT_LT(truth, 1.5);  // the ray-cast pixels' mean against the closed form
  EXPECT_GT(other, 10 * truth);
  // The penalty: none on the bone as it is, the squared gap on its flip (the others hidden).
  // depth_flip reflects the axis across the line of sight: near the hand-made flip (the sight
  // line is 5 degrees off the optical axis), and back again.
  const BoneSample reflected = depth_flip(bone);
  EXPECT_GT(reflected.axis.normalized().dot(flipped.normalized()), std::cos(0.2));
  EXPECT_LT((depth_flip(reflected).axis - bone.axis).norm(), 1e-12);
  const double gap = std::abs(bone.grey - predicted_grey(reflected, lighting));
  std::array<BoneSample, kShadedBones> bones{bone, {}, {}, {}};
  std::array<BoneSample, kShadedBones> flips{reflected, {}, {}, {}};
  EXPECT_EQ(flip_penalty(bones, lighting), 0.0);
  EXPECT_NEAR(flip_penalty(flips, lighting), gap * gap - truth * truth, 1e-6);
}

TEST(BoneShading, TheLightIsFittedFromAStartFramesPixels) {
  // A ball rendered by the capsule rasterizer, its pixels shaded with the ray-sphere normals
  // under a light from above and in front: the fit finds that light from the capsule's normals.
  const Camera cam = Camera::look_at("cam", 320, 240, std::numbers::pi / 3,
                                     Eigen::Vector3d(0, 1, 3), Eigen::Vector3d(0, 1, 0));
  const Eigen::Vector3d centre(0, 1, 0);
  const double radius = 0.3;
  BodyShape shape;
  Capsule ball;
  ball.a = ball.b = centre;
  ball.ra = ball.rb = radius;
  shape.capsules.push_back(ball);
  const std::vector<Eigen::Isometry3d> world{Eigen::Isometry3d::Identity()};
  const View view{&cam, 0, 0, 1, cam.width, cam.height};
  LabelImage cells;
  render_labels(shape, world, view, cells);
  const Eigen::Vector3d light_world = Eigen::Vector3d(0.3, 1.0, 0.4).normalized();
  const Eigen::Vector3d light = cam.R * light_world;
  cv::Mat image(cam.height, cam.width, CV_8UC3, cv::Scalar::all(0));
  cv::Mat silhouette(cam.height, cam.width, CV_8UC1, cv::Scalar(0));
  const Eigen::Vector3d c = cam.to_camera(centre);
  for (int v = 0; v < cam.height; ++v) {
    for (int u = 0; u < cam.width; ++u) {
      if (cells.at(u, v) == kNoCell) continue;
      const Eigen::Vector3d d = cam.K.inverse() * Eigen::Vector3d(u, v, 1);
      const double b = d.dot(c),
                   disc = b * b - d.squaredNorm() * (c.squaredNorm() - radius * radius);
      if (disc < 0) continue;
      const Eigen::Vector3d n = ((b - std::sqrt(disc)) / d.squaredNorm() * d - c) / radius;
      const double grey = 40 + 150 * std::max(0.0, n.dot(light));
      image.at<cv::Vec3b>(v, u) = cv::Vec3b::all(static_cast<std::uint8_t>(std::lround(grey)));
      silhouette.at<std::uint8_t>(v, u) = 255;
    }
  }
  const std::vector<std::uint8_t> cell_class(kCellsPerCapsule, 1);
  const std::vector<ShadedPixel> pixels =
      shaded_pixels(shape, world, view, cells, image, silhouette, cell_class);
  ASSERT_GT(pixels.size(), 500u);
  const LightFit fit = fit_light(pixels, cam.R * Eigen::Vector3d::UnitY());
  EXPECT_GT(fit.lighting.to_light.dot(light), std::cos(5 * std::numbers::pi / 180));
  EXPECT_NEAR(fit.lighting.albedo[1], 150, 15);
  EXPECT_NEAR(fit.lighting.offset[1], 40, 5);
  EXPECT_FALSE(fit_light({}, Eigen::Vector3d::UnitY()).lighting.known());
}

}  // namespace
}  // namespace simcap::tracker::gomez
