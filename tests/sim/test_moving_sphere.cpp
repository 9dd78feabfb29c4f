// The renderer's time against analytic answers: a sphere moving at constant velocity across a
// camera's view (Embree motion blur, two or three vertex time steps interpolate the motion
// exactly; with three, a still copy of the middle one as the renderer's blur uses). A
// rolling shutter shows each row the sphere where it was when that row was captured; a motion-
// blurred render covers each pixel the fraction of the exposure and pixel area the sphere did.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/camera.h"
#include "models/body_mesh.h"
#include "scenes/scene.h"
#include "sim/camera_rays.h"
#include "sim/embree_scene.h"
#include "sim/renderer.h"
#include "sim/srgb.h"

namespace simcap {
namespace {

constexpr int kRings = 48, kSegments = 96;
constexpr double kRadius = 0.3;

// A UV sphere around the origin, faces wound outwards, one material and one part.
BodyMesh sphere_mesh() {
  BodyMesh m;
  m.vertices.push_back({0, static_cast<float>(kRadius), 0});
  for (int i = 1; i < kRings; ++i) {
    const double theta = std::numbers::pi * i / kRings;
    for (int j = 0; j < kSegments; ++j) {
      const double phi = 2 * std::numbers::pi * j / kSegments;
      m.vertices.push_back(
          (kRadius * Eigen::Vector3d(std::sin(theta) * std::cos(phi), std::cos(theta),
                                     -std::sin(theta) * std::sin(phi)))
              .cast<float>());
    }
  }
  m.vertices.push_back({0, static_cast<float>(-kRadius), 0});
  const auto ring = [](int i, int j) {
    return static_cast<std::uint32_t>(1 + (i - 1) * kSegments + (j % kSegments));
  };
  const auto bottom = static_cast<std::uint32_t>(m.vertices.size() - 1);
  for (int j = 0; j < kSegments; ++j) {
    m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
    for (int i = 1; i + 1 < kRings; ++i) {
      m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
    m.triangles.push_back({ring(kRings - 1, j), bottom, ring(kRings - 1, j + 1)});
  }
  m.triangle_material.assign(m.triangles.size(), MaterialRegion::skin);
  m.vertex_segment.assign(m.vertices.size(), 0);
  return m;
}

// Where the inscribed polyhedron may differ from the sphere: rays this close to the rim (in
// distance from the centre) are not judged.
double rim_band() {
  return 2 * kRadius * (1 - std::cos(std::numbers::pi / kRings));
}

// A white sphere lit by ambient light only, in front of a camera at the origin looking down -Z,
// moving from `start` to `end` over Embree's time [0, 1].
struct MovingSphere {
  Scene scene;
  Camera camera =
      Camera::look_at("cam", 80, 60, 60 * std::numbers::pi / 180, {0, 0, 0}, {0, 0, -1});
  BodyMesh mesh = sphere_mesh();
  // Two time steps, or three with a still copy of the middle one (the renderer's blur setting).
  const int steps;
  EmbreeScene embree;
  Eigen::Vector3d start{-0.7, 0.1, -3}, end{0.7, -0.1, -3};

  explicit MovingSphere(int samples, int time_steps = 2)
      : steps(time_steps), embree(BodyBvhUpdate::rebuild, time_steps, time_steps == 3 ? 1 : -1) {
    scene.lights.clear();
    scene.ambient = 1;
    scene.render.samples_per_pixel = samples;
    const int body = embree.add_body(mesh, false);
    std::array<Rgb, kMaterialRegionCount> white;
    white.fill(Rgb(1, 1, 1));
    embree.add_actor(body, white);
    for (int step = 0; step < steps; ++step) {
      const Eigen::Vector3f c = centre(static_cast<double>(step) / (steps - 1)).cast<float>();
      float* v = embree.body_vertices(body, step);
      for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        for (int k = 0; k < 3; ++k) v[3 * i + k] = mesh.vertices[i][k] + c[k];
      }
    }
    embree.body_updated(body);
    embree.commit();
  }
  Eigen::Vector3d centre(double time) const { return start + time * (end - start); }

  RenderedView render(const RayTimes& times) const {
    const Renderer renderer(embree, scene);
    const CameraRays rays(camera);
    Renderer::Shot shot;
    shot.rays = &rays;
    shot.times = times;
    std::vector<RenderedView> views;
    renderer.render({shot}, 0, views, false);
    return views.at(0);
  }

  // Distance from the sphere's centre at `time` to the ray through pixel position (x, y).
  double miss_distance(double x, double y, double time) const {
    const Eigen::Vector3d d = camera.unproject({x, y});
    const Eigen::Vector3d c = centre(time);
    return (c - c.dot(d) * d).norm();
  }
};

TEST(MovingSphere, RollingShutterShowsEachRowTheSphereWhenTheRowWasCaptured) {
  const MovingSphere s(1);
  const int h = s.camera.height;
  RayTimes rolling;
  rolling.per_row = 1.f / static_cast<float>(h - 1);
  const cv::Mat mask = s.render(rolling).mask;
  const cv::Mat global = s.render(RayTimes{}).mask;
  int judged = 0, hits = 0, skewed = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < s.camera.width; ++x) {
      const double d = s.miss_distance(x, y, rolling.at_row(y));
      skewed += mask.at<std::uint8_t>(y, x) != global.at<std::uint8_t>(y, x);
      if (std::abs(d - kRadius) < rim_band()) continue;
      ++judged;
      hits += d < kRadius;
      EXPECT_EQ(mask.at<std::uint8_t>(y, x), d < kRadius ? 255 : 0) << x << ", " << y;
    }
  }
  EXPECT_GT(judged, 4500);
  EXPECT_GT(hits, 100);
  // The sphere crosses 1.4 m while the rows are read: the skew is tens of pixels.
  EXPECT_GT(skewed, 300);
}

// The fraction of [0, 1] during which the ray through (x, y) meets the sphere: the ray's
// distance to the moving centre is |p0 + t dp|, below the radius on one interval of t.
double time_covered(const MovingSphere& s, double x, double y) {
  const Eigen::Vector3d d = s.camera.unproject({x, y});
  auto perpendicular = [&](const Eigen::Vector3d& c) { return Eigen::Vector3d(c - c.dot(d) * d); };
  const Eigen::Vector3d p0 = perpendicular(s.centre(0));
  const Eigen::Vector3d dp = perpendicular(s.centre(1)) - p0;
  const double a = dp.squaredNorm(), b = 2 * p0.dot(dp), c = p0.squaredNorm() - kRadius * kRadius;
  const double disc = b * b - 4 * a * c;
  if (disc <= 0) return 0;
  const double t0 = (-b - std::sqrt(disc)) / (2 * a), t1 = (-b + std::sqrt(disc)) / (2 * a);
  return std::max(0.0, std::min(1.0, t1) - std::max(0.0, t0));
}

class MovingSphereBlur : public testing::TestWithParam<int> {};

// With three steps the pixel-centre rays trace the still copy of the middle step, and the other
// samples the still scene too wherever they pass the sphere's path at a distance: a ray sent
// there by mistake would miss the sphere and show in the coverage.
TEST_P(MovingSphereBlur, CoversEachPixelAsTheSphereDidOverTheExposure) {
  constexpr int kSamples = 256, kSub = 8;
  const MovingSphere s(kSamples, GetParam());
  RayTimes exposure;
  exposure.row0 = 0.5f;
  exposure.exposure = 1.f;
  const RenderedView v = s.render(exposure);
  double error_sum = 0, rendered_total = 0, analytic_total = 0;
  int blurred = 0, labelled = 0;
  for (int y = 0; y < s.camera.height; ++y) {
    for (int x = 0; x < s.camera.width; ++x) {
      // Analytic in time, an 8 x 8 grid over the pixel's area.
      double coverage = 0;
      for (int i = 0; i < kSub; ++i) {
        for (int j = 0; j < kSub; ++j) {
          coverage += time_covered(s, x - 0.5 + (i + 0.5) / kSub, y - 0.5 + (j + 0.5) / kSub);
        }
      }
      coverage /= kSub * kSub;
      const double rendered = srgb_to_linear(v.rgb.at<cv::Vec3b>(y, x)[1] / 255.f);
      error_sum += std::abs(rendered - coverage);
      rendered_total += rendered;
      analytic_total += coverage;
      blurred += coverage > 0.05 && coverage < 0.95;
      // Labels come from the pixel centre at the exposure's middle: the sharp sphere.
      const double d = s.miss_distance(x, y, 0.5);
      if (std::abs(d - kRadius) >= rim_band()) {
        ++labelled;
        EXPECT_EQ(v.mask.at<std::uint8_t>(y, x), d < kRadius ? 255 : 0) << x << ", " << y;
      }
    }
  }
  EXPECT_GT(blurred, 300);  // a streak, not a disc
  EXPECT_GT(labelled, 4500);
  // 256 samples stratified over the exposure: per-pixel noise of a few percent at most.
  EXPECT_LT(error_sum / blurred, 0.02);
  EXPECT_NEAR(rendered_total, analytic_total, 0.01 * analytic_total);
}

INSTANTIATE_TEST_SUITE_P(TimeSteps, MovingSphereBlur, testing::Values(2, 3));

TEST(MovingSphere, RaysFarFromTheSpheresPathTraceTheStillScene) {
  const MovingSphere s(1, 3);
  const RTCScene moving = s.embree.handle();
  const RTCScene still = s.embree.scene_at(0.5f);
  EXPECT_NE(still, moving);
  EXPECT_EQ(s.embree.scene_at(0.25f), moving);
  constexpr int N = 4;
  // From the camera: towards the sphere's start, its end, above the path, beside it.
  const float target[N][3] = {{-0.7f, 0.1f, -3}, {0.7f, -0.1f, -3}, {0, 0.5f, -3}, {1.3f, 0, -3}};
  alignas(16) float org[3][N] = {}, dir[3][N], far[N];
  for (int k = 0; k < N; ++k) {
    for (int c = 0; c < 3; ++c) dir[c][k] = target[k][c];
    far[k] = std::numeric_limits<float>::infinity();
  }
  const float* const o[3] = {org[0], org[1], org[2]};
  const float* const d[3] = {dir[0], dir[1], dir[2]};
  for (int k = 0; k < N; ++k) {
    alignas(16) int valid[N] = {};
    valid[k] = -1;
    EXPECT_EQ(s.embree.scene_for<N>(valid, o, d, far), k < 2 ? moving : still) << k;
  }
  // A ray that ends before the path does not need it either.
  alignas(16) int valid[N] = {-1, 0, 0, 0};
  const float short_ray[N] = {0.5f, 0, 0, 0};
  EXPECT_EQ(s.embree.scene_for<N>(valid, o, d, short_ray), still);
}

}  // namespace
}  // namespace simcap
