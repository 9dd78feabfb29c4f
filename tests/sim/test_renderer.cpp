// The renderer against geometry whose images are known in closed form: a plane's depth, a
// sphere's silhouette area predicted through cv::projectPoints, the sRGB curve, textures.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <opencv2/imgproc.hpp>

#include "core/image_io.h"
#include "sim/camera_rays.h"
#include "sim/embree_scene.h"
#include "sim/renderer.h"
#include "sim/srgb.h"
#include "sim/texture.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

// A camera with visible lens distortion, so that per-pixel rays are exercised.
Camera distorted_camera(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  Camera c = Camera::look_at("cam", 320, 240, 70 * M_PI / 180, eye, target);
  c.dist << -0.25, 0.08, 0.001, -0.0015, -0.01;
  return c;
}

TriangleMesh quad(const Eigen::Vector3f& centre, const Eigen::Vector3f& u,
                  const Eigen::Vector3f& v) {
  TriangleMesh m;
  m.vertices = {centre - u - v, centre + u - v, centre + u + v, centre - u + v};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// Latitude-longitude sphere, fine enough that its silhouette is within 1e-4 of the sphere's.
TriangleMesh sphere(const Eigen::Vector3f& centre, float radius) {
  constexpr int kLon = 512, kLat = 256;
  TriangleMesh m;
  for (int i = 0; i <= kLat; ++i) {
    const double theta = M_PI * i / kLat;
    for (int j = 0; j < kLon; ++j) {
      const double phi = 2 * M_PI * j / kLon;
      m.vertices.push_back(
          centre + radius * Eigen::Vector3f(static_cast<float>(std::sin(theta) * std::cos(phi)),
                                            static_cast<float>(std::cos(theta)),
                                            static_cast<float>(std::sin(theta) * std::sin(phi))));
    }
  }
  for (std::uint32_t i = 0; i < kLat; ++i) {
    for (std::uint32_t j = 0; j < kLon; ++j) {
      const std::uint32_t a = i * kLon + j, b = i * kLon + (j + 1) % kLon;
      m.triangles.push_back({a, a + kLon, b + kLon});
      m.triangles.push_back({a, b + kLon, b});
    }
  }
  return m;
}

RenderedView render_one(const EmbreeScene& embree, const Scene& scene, const Camera& camera) {
  Renderer renderer(embree, scene);
  std::vector<CameraRays> rays;
  rays.emplace_back(camera);
  std::vector<RenderedView> views;
  renderer.render(rays, 0, views);
  return views.at(0);
}

TEST(Renderer, PlaneFacingTheCameraHasItsDistanceAsDepthInEveryPixel) {
  const Eigen::Vector3d eye(0.3, 1.2, -0.4), target(1.0, 1.5, 2.0);
  const Camera cam = distorted_camera(eye, target);
  const double z = 2.5;
  const Eigen::Vector3f centre = (eye + z * cam.R.row(2).transpose()).cast<float>();
  EmbreeScene embree;
  embree.add_static(quad(centre, 50.f * cam.R.row(0).transpose().cast<float>(),
                         50.f * cam.R.row(1).transpose().cast<float>()),
                    {}, true);
  embree.commit();
  const RenderedView view = render_one(embree, Scene{}, cam);
  ASSERT_EQ(view.depth.type(), CV_32FC1);
  double worst = 0;
  for (int y = 0; y < view.depth.rows; ++y) {
    for (int x = 0; x < view.depth.cols; ++x) {
      worst = std::max(worst, std::abs(view.depth.at<float>(y, x) - z));
    }
  }
  EXPECT_LT(worst, 1e-5 * z);
  EXPECT_EQ(cv::countNonZero(view.mask), 0);  // no actor
  EXPECT_EQ(cv::countNonZero(view.parts), 0);
}

TEST(Renderer, NothingHitGivesInfiniteDepth) {
  EmbreeScene embree;
  embree.commit();
  const RenderedView view = render_one(embree, Scene{}, distorted_camera({0, 1, 0}, {0, 1, 1}));
  for (int y = 0; y < view.depth.rows; ++y) {
    for (int x = 0; x < view.depth.cols; ++x) {
      ASSERT_TRUE(std::isinf(view.depth.at<float>(y, x)) && view.depth.at<float>(y, x) > 0);
    }
  }
}

TEST(Renderer, SphereCoversThePixelAreaTheCameraModelPredicts) {
  const Camera cam = distorted_camera({0.2, 1.4, -2.0}, {0.0, 1.0, 1.0});
  // Off-axis, so that distortion changes the silhouette's shape and size.
  const Eigen::Vector3d centre_cam(0.55, -0.3, 3.2);
  const double r = 0.45;
  EmbreeScene embree;
  embree.add_static(sphere(cam.to_world(centre_cam).cast<float>(), static_cast<float>(r)), {},
                    true);
  embree.commit();
  const RenderedView view = render_one(embree, Scene{}, cam);
  int covered = 0;
  for (int y = 0; y < view.depth.rows; ++y) {
    for (int x = 0; x < view.depth.cols; ++x) covered += std::isfinite(view.depth.at<float>(y, x));
  }
  // The silhouette is the circle where the tangent cone from the camera centre touches the
  // sphere; OpenCV projects it through the same lens model.
  const double d = centre_cam.norm();
  const Eigen::Vector3d axis = centre_cam / d;
  const Eigen::Vector3d u = axis.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d v = axis.cross(u);
  const Eigen::Vector3d circle_centre = centre_cam * (1 - r * r / (d * d));
  const double circle_radius = r * std::sqrt(1 - r * r / (d * d));
  std::vector<cv::Point3d> rim;
  for (int i = 0; i < 4000; ++i) {
    const double a = 2 * M_PI * i / 4000;
    const Eigen::Vector3d p = circle_centre + circle_radius * (std::cos(a) * u + std::sin(a) * v);
    rim.emplace_back(p.x(), p.y(), p.z());
  }
  cv::Mat K, dist;
  cv::eigen2cv(cam.K, K);
  cv::eigen2cv(Eigen::MatrixXd(cam.dist.transpose()), dist);
  std::vector<cv::Point2d> projected;
  cv::projectPoints(rim, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), K, dist, projected);
  const std::vector<cv::Point2f> outline(projected.begin(), projected.end());
  const double predicted = cv::contourArea(outline);
  ASSERT_GT(predicted, 3000);  // big enough for pixel counting to resolve 1%
  EXPECT_NEAR(covered, predicted, 0.01 * predicted);
}

TEST(Renderer, LambertShadingWithAndWithoutShadow) {
  // A floor lit straight from above, half of it under a floating box.
  Scene scene;
  scene.ambient = 0.2;
  Light light;
  light.direction = {0, -1, 0};
  light.intensity = 0.7;
  scene.lights = {light};
  EmbreeScene embree;
  StaticLook white;
  white.color = {1.f, 1.f, 1.f};
  embree.add_static(quad({0, 0, 0}, {5, 0, 0}, {0, 0, 5}), white, false);
  embree.add_static(quad({-2.5f, 1, 0}, {2.5f, 0, 0}, {0, 0, 5}), white, true);
  embree.commit();
  const Camera cam = Camera::look_at("cam", 64, 48, 1.0, {0.01, 0.5, 0}, {0.01, -1, 0.0},
                                     Eigen::Vector3d::UnitZ());
  const RenderedView view = render_one(embree, scene, cam);
  const SrgbEncoder encode;
  // +X is on the image's left here (looking down with +Z up in the image).
  EXPECT_EQ(view.rgb.at<cv::Vec3b>(24, 10)[0], encode(0.2f + 0.7f));  // lit floor at x > 0
  EXPECT_EQ(view.rgb.at<cv::Vec3b>(24, 54)[0], encode(0.2f));         // box shadow at x < 0
}

// Shadow rays trace a scene of the shadow casters alone: a ray down through a caster and the
// floor meets the caster under the same geometry id, one beside it meets nothing, while camera
// rays meet both; likewise for the still scene that motion blur adds.
TEST(EmbreeScene, ShadowRaysTraceOnlyTheShadowCastersExceptInMotionBlurScenes) {
  auto first_hit = [](RTCScene scene, float x) {
    RTCRayHit rh{};
    rh.ray.org_x = x;
    rh.ray.org_y = 3;
    rh.ray.dir_y = -1;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene, &context, &rh);
    return rh.hit.geomID;
  };
  // A caster above the left half of a floor that casts no shadows.
  auto check_casters = [&](RTCScene camera_scene, RTCScene casters) {
    EXPECT_NE(casters, camera_scene);
    const unsigned caster = first_hit(camera_scene, -1.f), floor = first_hit(camera_scene, 1.f);
    ASSERT_NE(caster, RTC_INVALID_GEOMETRY_ID);
    ASSERT_NE(floor, RTC_INVALID_GEOMETRY_ID);
    EXPECT_NE(caster, floor);
    EXPECT_EQ(first_hit(casters, -1.f), caster);
    EXPECT_EQ(first_hit(casters, 1.f), RTC_INVALID_GEOMETRY_ID);
  };
  auto add_room = [](EmbreeScene& embree) {
    embree.add_static(quad({0, 0, 0}, {5, 0, 0}, {0, 0, 5}), {}, false);
    embree.add_static(quad({-2.5f, 1, 0}, {2.5f, 0, 0}, {0, 0, 5}), {}, true);
    embree.commit();
  };
  EmbreeScene still(BodyBvhUpdate::refit);
  add_room(still);
  check_casters(still.handle(), still.casters_of(still.handle()));
  // A second copy would build the bodies' motion-blur BVHs twice a frame: the motion-blur scene's
  // shadow rays trace it whole (their mask rejects the room), its still copy's the casters'.
  EmbreeScene blurred(BodyBvhUpdate::refit, 3, 1);
  add_room(blurred);
  EXPECT_EQ(blurred.casters_of(blurred.handle()), blurred.handle());
  check_casters(blurred.scene_at(0.5f), blurred.casters_of(blurred.scene_at(0.5f)));
}

TEST(CameraRays, PixelRaysAreTheCameraModelsAndJitteredRaysInterpolateIt) {
  const Camera cam = distorted_camera({0.2, 1.4, -2.0}, {0.0, 1.0, 1.0});
  const CameraRays rays(cam);
  double worst_centre = 0, worst_jitter = 0;
  for (int y = 0; y < cam.height; y += 7) {
    for (int x = 0; x < cam.width; x += 5) {
      const Eigen::Vector3d exact = cam.unproject({double(x), double(y)});
      worst_centre = std::max(worst_centre, (rays.direction(x, y).cast<double>() - exact).norm());
      EXPECT_NEAR(rays.z_scale(x, y), (cam.R * exact).z(), 1e-6);
      const float jx = 0.5f * static_cast<float>((x * 37 + y * 11) % 21 - 10) / 10;
      const float jy = 0.5f * static_cast<float>((x * 13 + y * 29) % 21 - 10) / 10;
      const Eigen::Vector3d jittered = cam.unproject({x + jx, y + jy});
      worst_jitter = std::max(
          worst_jitter, (rays.jittered_direction(x, y, jx, jy).cast<double>() - jittered).norm());
    }
  }
  // The last row and column use the outermost pixel corners.
  const Eigen::Vector3d corner = cam.unproject({cam.width - 0.5, cam.height - 0.5});
  worst_jitter = std::max(
      worst_jitter,
      (rays.jittered_direction(cam.width - 1, cam.height - 1, 0.5f, 0.5f).cast<double>() - corner)
          .norm());
  EXPECT_LT(worst_centre, 1e-6);  // float precision
  EXPECT_LT(worst_jitter, 1e-5);  // ~0.005 px at this focal length
}

TEST(CameraRays, BlockOfJitteredRaysIsBitIdenticalToSingleRays) {
  const Camera cam = distorted_camera({0.2, 1.4, -2.0}, {0.0, 1.0, 1.0});
  const CameraRays rays(cam);
  constexpr int N = CameraRays::kLanes, B = CameraRays::kBlock;
  for (int py = 0; py < cam.height; py += 3 * B) {
    for (int px = 0; px < cam.width; px += 5 * B) {
      alignas(64) float jx[N], jy[N], dx[N], dy[N], dz[N];
      alignas(64) int valid[N];
      for (int k = 0; k < N; ++k) {
        jx[k] = static_cast<float>((px * 37 + py * 11 + k * 7) % 101) / 100 - 0.5f;
        jy[k] = static_cast<float>((px * 13 + py * 29 + k * 5) % 101) / 100 - 0.5f;
        valid[k] = px + k % B < cam.width && py + k / B < cam.height && k != 6 ? -1 : 0;
      }
      rays.jittered_block(px, py, jx, jy, valid, dx, dy, dz);
      for (int k = 0; k < N; ++k) {
        const Eigen::Vector3f d = valid[k] ? rays.jittered_ray(px + k % B, py + k / B, jx[k], jy[k])
                                           : Eigen::Vector3f(Eigen::Vector3f::UnitZ());
        // Bit for bit: the renderer's images must not depend on which of the two it calls.
        EXPECT_EQ(dx[k], d.x()) << px << "," << py << " lane " << k;
        EXPECT_EQ(dy[k], d.y()) << px << "," << py << " lane " << k;
        EXPECT_EQ(dz[k], d.z()) << px << "," << py << " lane " << k;
      }
    }
  }
}

TEST(Srgb, EncoderInvertsTheTransferCurveForEveryCode) {
  const SrgbEncoder encode;
  for (int code = 0; code < 256; ++code) {
    EXPECT_EQ(encode(srgb_to_linear(code / 255.f)), code) << code;
  }
  for (int first = 0; first < 256; first += SrgbEncoder::kBatch) {
    float linear[SrgbEncoder::kBatch];
    std::uint8_t codes[SrgbEncoder::kBatch];
    for (int i = 0; i < SrgbEncoder::kBatch; ++i) {
      linear[i] = srgb_to_linear(std::min(255, first + i) / 255.f);
    }
    encode.encode(linear, codes);
    for (int i = 0; i < SrgbEncoder::kBatch; ++i) EXPECT_EQ(codes[i], std::min(255, first + i));
  }
  EXPECT_EQ(encode(-1.f), 0);
  EXPECT_EQ(encode(7.f), 255);
}

// Every pixel's linear colour is exactly ambient x albedo + (intensity x cosine) x albedo with
// each operation rounded on its own, as the baseline code computes it; the shading loops run as
// AVX2 clones where the CPU has them (sim/avx2_clones.h) and must give the same bits. Auto
// exposure keeps the linear colour per pixel.
TEST(Renderer, LinearColourRoundsEachOperationOnItsOwn) {
  Scene scene;
  scene.ambient = 0.3;
  scene.timing.auto_exposure = true;
  Light light;
  light.direction = {-0.3, -1.0, -0.4};
  light.intensity = 0.8;
  scene.lights = {light};
  EmbreeScene embree;
  StaticLook look;
  look.color = {0.53f, 0.65f, 0.41f};  // red and green: a fused multiply-add rounds differently
  embree.add_static(quad({0, 0, 0}, {5, 0, 0}, {0, 0, 5}), look, false);
  embree.commit();
  const Camera cam = Camera::look_at("cam", 64, 48, 1.0, {0.01, 0.5, 0}, {0.01, -1, 0.0},
                                     Eigen::Vector3d::UnitZ());
  const RenderedView view = render_one(embree, scene, cam);
  const Eigen::Vector3f albedo = srgb_to_linear(look.color);
  const float ambient = static_cast<float>(scene.ambient);
  const float intensity = static_cast<float>(light.intensity);
  // The floor's normal is +Y, so the cosine is the light direction's y.
  const float cosine = (-light.direction).normalized().cast<float>().y();
  volatile float weight = intensity * cosine;  // volatile: no contraction here either
  cv::Vec3f expected;
  for (int c = 0; c < 3; ++c) {
    volatile const float lit = weight * albedo[c];
    expected[c] = ambient * albedo[c] + lit;
  }
  int mismatches = 0;
  for (int y = 0; y < view.linear.rows; ++y) {
    for (int x = 0; x < view.linear.cols; ++x) {
      mismatches += view.linear.at<cv::Vec3f>(y, x) != expected ? 1 : 0;
    }
  }
  EXPECT_EQ(mismatches, 0) << view.linear.at<cv::Vec3f>(24, 32) << " vs " << expected;
}

TEST(Texture, SamplesTexelCentresAndRepeatsEveryMetre) {
  testing::TempDir dir;
  cv::Mat image(2, 2, CV_8UC3);
  image.at<cv::Vec3b>(0, 0) = {255, 0, 0};
  image.at<cv::Vec3b>(0, 1) = {0, 255, 0};
  image.at<cv::Vec3b>(1, 0) = {0, 0, 255};
  image.at<cv::Vec3b>(1, 1) = {255, 255, 255};
  write_image(dir / "t.png", image);
  const Texture texture(dir / "t.png");
  EXPECT_TRUE(texture.sample(0.25f, 0.25f).isApprox(Eigen::Vector3f(1, 0, 0)));
  EXPECT_TRUE(texture.sample(0.75f, 0.25f).isApprox(Eigen::Vector3f(0, 1, 0)));
  EXPECT_TRUE(texture.sample(0.25f, 0.75f).isApprox(Eigen::Vector3f(0, 0, 1)));
  EXPECT_TRUE(texture.sample(3.75f, -0.25f).isApprox(Eigen::Vector3f(1, 1, 1)));
  // Halfway between two texels: the mean of their linear values.
  EXPECT_TRUE(texture.sample(0.5f, 0.25f).isApprox(Eigen::Vector3f(0.5f, 0.5f, 0)));
}

}  // namespace
}  // namespace simcap
