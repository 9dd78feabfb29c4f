// The scene keys of capture nuisances: each is off by default and then absent from the resolved
// scene, round-trips exactly when on and is reached by --set overrides; light keyframes
// interpolate as documented. Their bad values are cases of test_scene_errors.cpp.
#include <gtest/gtest.h>

#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::load_error;
using simcap::testing::TempDir;
using simcap::testing::write_scene;

const char* kNuisances = R"(
lights:
  - type: point
    position: [0, 2.5, 0]
    keyframes:
      - {time: 0, intensity: 0.2}
      - {time: 1.5, position: [1, 2.5, 0]}
      - {time: 2, intensity: 1.1, position: [1, 2, -1]}
  - type: directional
    direction: [0, -1, 0]
    keyframes: [{time: -1, direction: [0, -1, 0]}, {time: 1, direction: [1, -1, 0]}]
rig:
  calibration_error: {rotation_deg: 0.5, translation_m: 0.01, focal_rel: 0.02, principal_px: 1.5,
                      seed: 7}
  sync: {offset_ms: [0, 12.5, -3.25, 40]}
  readout_ms: 28.5
  auto_exposure: true
render: {frames: 3, shutter: 0.5, samples_per_pixel: 4}
)";

TEST(CaptureKeys, OffByDefaultAndNotWritten) {
  TempDir dir;
  const Scene s = load_scene(write_scene(dir.path(), "render: {frames: 2}\n"));
  EXPECT_FALSE(s.calibration_error.any());
  EXPECT_TRUE(s.timing.synchronised());
  EXPECT_EQ(s.timing.readout_ms, 0);
  EXPECT_FALSE(s.timing.auto_exposure);
  EXPECT_EQ(s.render.shutter, 0);
  EXPECT_TRUE(s.lights.at(0).keyframes.empty());
  const std::string text = scene_to_yaml(s);
  for (const char* key :
       {"calibration_error", "sync", "readout_ms", "auto_exposure", "shutter", "keyframes"}) {
    EXPECT_EQ(text.find(key), std::string::npos) << key;
  }
}

TEST(CaptureKeys, RoundTripExactly) {
  TempDir dir;
  const Scene a = load_scene(write_scene(dir.path(), kNuisances));
  EXPECT_EQ(a.calibration_error.rotation_deg, 0.5);
  EXPECT_EQ(a.calibration_error.seed, 7u);
  EXPECT_EQ(a.timing.offset_ms, (std::vector<double>{0, 12.5, -3.25, 40}));
  EXPECT_EQ(a.timing.readout_ms, 28.5);
  EXPECT_EQ(a.render.shutter, 0.5);
  ASSERT_EQ(a.lights.at(0).keyframes.size(), 3u);
  const std::string text = scene_to_yaml(a);
  const Scene b = load_scene(write_scene(dir.path(), text, "resolved.yaml"));
  simcap::testing::expect_scenes_equal(a, b);
  EXPECT_EQ(scene_to_yaml(b), text);
  EXPECT_EQ(b.calibration_error.focal_rel, a.calibration_error.focal_rel);
  EXPECT_EQ(b.calibration_error.principal_px, a.calibration_error.principal_px);
  EXPECT_EQ(b.calibration_error.translation_m, a.calibration_error.translation_m);
  EXPECT_EQ(b.timing.offset_ms, a.timing.offset_ms);
  EXPECT_EQ(b.timing.readout_ms, a.timing.readout_ms);
  EXPECT_TRUE(b.timing.auto_exposure);
  EXPECT_EQ(b.render.shutter, a.render.shutter);
  for (size_t i = 0; i < a.lights.size(); ++i) {
    ASSERT_EQ(b.lights[i].keyframes.size(), a.lights[i].keyframes.size());
    for (size_t k = 0; k < a.lights[i].keyframes.size(); ++k) {
      const LightKeyframe &x = a.lights[i].keyframes[k], &y = b.lights[i].keyframes[k];
      EXPECT_EQ(x.time_s, y.time_s);
      EXPECT_EQ(x.intensity, y.intensity);
      EXPECT_EQ(x.position, y.position);
      EXPECT_EQ(x.direction, y.direction);
    }
  }
}

TEST(CaptureKeys, SigmaOffsetsRoundTripAsSigmaAndSeed) {
  TempDir dir;
  const Scene a = load_scene(
      write_scene(dir.path(), "rig: {sync: {offset_ms_sigma: 8, seed: 3}}\nrender: {frames: 2}\n"));
  EXPECT_FALSE(a.timing.synchronised());
  EXPECT_TRUE(a.timing.offset_ms.empty());
  const Scene b = load_scene(write_scene(dir.path(), scene_to_yaml(a), "resolved.yaml"));
  EXPECT_EQ(b.timing.offset_sigma_ms, 8);
  EXPECT_EQ(b.timing.seed, 3u);
}

TEST(CaptureKeys, LightKeyframesInterpolateEachValueBetweenTheKeyframesGivingIt) {
  TempDir dir;
  const Scene s = load_scene(write_scene(dir.path(), kNuisances));
  const Light& point = s.lights[0];
  EXPECT_DOUBLE_EQ(light_at(point, -5).intensity, 0.2);  // held before the first
  EXPECT_DOUBLE_EQ(light_at(point, 1.0).intensity, 0.2 + 0.5 * 0.9);
  EXPECT_DOUBLE_EQ(light_at(point, 9).intensity, 1.1);  // held after the last
  // The position is keyed at 1.5 and 2 only; before 1.5 it holds the first key, not the base.
  EXPECT_TRUE(light_at(point, 0.5).position.isApprox(Eigen::Vector3d(1, 2.5, 0)));
  EXPECT_TRUE(light_at(point, 1.75).position.isApprox(Eigen::Vector3d(1, 2.25, -0.5)));
  const Light& sun = s.lights[1];
  const Eigen::Vector3d mid =
      0.5 * Eigen::Vector3d(0, -1, 0) + 0.5 * Eigen::Vector3d(1, -1, 0).normalized();
  EXPECT_TRUE(light_at(sun, 0).direction.isApprox(mid.normalized()));
  EXPECT_NEAR(light_at(sun, 0.3).direction.norm(), 1, 1e-12);
}

TEST(CaptureKeys, OverridesReachTheNewKeys) {
  TempDir dir;
  const auto path = write_scene(dir.path(), "render: {frames: 2}\n");
  const Scene s = load_scene(path, {"rig.readout_ms=12", "render.shutter=0.25",
                                    "render.samples_per_pixel=2", "rig.sync={offset_ms_sigma: 5}"});
  EXPECT_EQ(s.timing.readout_ms, 12);
  EXPECT_EQ(s.render.shutter, 0.25);
  EXPECT_EQ(s.timing.offset_sigma_ms, 5);
  EXPECT_NE(load_error(path, {"rig.readout_ms=x"}).find("override 'rig.readout_ms=x'"),
            std::string::npos);
}

}  // namespace
}  // namespace simcap
