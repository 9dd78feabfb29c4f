// rig.jitter: each camera moved within the stated bounds about its own centre, keyed by the seed
// and the camera's name, written into the resolved scene as the jittered cameras themselves.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "scenes/camera_jitter.h"
#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::load_error;
using simcap::testing::TempDir;
using simcap::testing::write_scene;

Scene with_jitter(const TempDir& dir, const std::string& jitter) {
  return load_scene(write_scene(dir.path(), "rig: {type: ring, count: 6, radius: 1.5, jitter: " +
                                                jitter + "}\nrender: {frames: 2}\n"));
}

TEST(CameraJitter, MovesEachCameraWithinItsBounds) {
  TempDir dir;
  const Scene still = with_jitter(dir, "{}");
  const Scene moved = with_jitter(dir, "{position_m: 0.05, rotation_deg: 2, seed: 9}");
  ASSERT_EQ(still.cameras.size(), moved.cameras.size());
  double largest_shift = 0, largest_turn = 0;
  for (size_t i = 0; i < still.cameras.size(); ++i) {
    const Camera &a = still.cameras[i], &b = moved.cameras[i];
    simcap::testing::expect_cameras_equal(a, with_jitter(dir, "{seed: 9}").cameras[i], 0);
    EXPECT_EQ(a.K, b.K);
    const Eigen::Vector3d shift = b.centre() - a.centre();
    EXPECT_LE(shift.cwiseAbs().maxCoeff(), 0.05 + 1e-12) << a.name;
    const double turn_deg =
        Eigen::AngleAxisd(b.R * a.R.transpose()).angle() * 180 / std::numbers::pi;
    EXPECT_LE(turn_deg, 2 + 1e-9) << a.name;
    EXPECT_LE(std::abs(b.R.determinant() - 1), 1e-12);
    largest_shift = std::max(largest_shift, shift.cwiseAbs().maxCoeff());
    largest_turn = std::max(largest_turn, turn_deg);
  }
  // Six cameras drawing uniformly do not all stay near zero.
  EXPECT_GT(largest_shift, 0.01);
  EXPECT_GT(largest_turn, 0.2);
}

TEST(CameraJitter, KeyedBySeedAndNameAndWrittenAsTheCameras) {
  TempDir dir;
  const Scene a = with_jitter(dir, "{position_m: 0.1, rotation_deg: 5, seed: 3}");
  const Scene b = with_jitter(dir, "{position_m: 0.1, rotation_deg: 5, seed: 4}");
  EXPECT_NE((a.cameras[0].t - b.cameras[0].t).norm(), 0);
  // A camera's jitter follows its name, not its place in the rig.
  const Scene still = with_jitter(dir, "{}");
  const CameraJitter j{0.1, 5, 3};
  simcap::testing::expect_cameras_equal(jittered(still.cameras[1], j), a.cameras[1], 1e-12);
  Camera other = still.cameras[1];
  other.name = still.cameras[2].name;
  EXPECT_GT((jittered(other, j).t - a.cameras[1].t).norm(), 0);
  // The resolved scene holds the jittered cameras and no jitter key: it reloads unchanged.
  const std::string text = scene_to_yaml(a);
  EXPECT_EQ(text.find("jitter"), std::string::npos);
  const Scene again = load_scene(write_scene(dir.path(), text, "resolved.yaml"));
  for (size_t i = 0; i < a.cameras.size(); ++i) {
    simcap::testing::expect_cameras_equal(a.cameras[i], again.cameras[i], 1e-12);
  }
  // Reached by overrides, as a collection sets it.
  const Scene set =
      load_scene(write_scene(dir.path(),
                             "rig: {type: ring, count: 6, radius: 1.5}\n"
                             "render: {frames: 2}\n"),
                 {"rig.jitter.position_m=0.1", "rig.jitter.rotation_deg=5", "rig.jitter.seed=3"});
  simcap::testing::expect_cameras_equal(a.cameras[2], set.cameras[2], 0);
}

TEST(CameraJitter, BadValuesNameTheKey) {
  TempDir dir;
  const auto error = [&](const std::string& jitter) {
    return load_error(write_scene(dir.path(), "rig:\n  jitter: " + jitter +
                                                  "\n"
                                                  "render: {frames: 2}\n"));
  };
  EXPECT_NE(error("{position_m: -0.1}").find("scene.yaml:2: rig.jitter.position_m"),
            std::string::npos)
      << error("{position_m: -0.1}");
  EXPECT_NE(error("{rotation_deg: 200}").find("rig.jitter.rotation_deg"), std::string::npos);
  EXPECT_NE(error("{positon_m: 0.1}").find("rig.jitter.positon_m: unknown key"), std::string::npos)
      << error("{positon_m: 0.1}");
  // Corner cameras sit 0.1 m from the walls: a jitter of 0.2 m could take them outside, whatever
  // the seed draws.
  EXPECT_NE(error("{position_m: 0.2, seed: 5}")
                .find("scene.yaml:2: rig.jitter: position_m 0.2 could move camera cam00"),
            std::string::npos)
      << error("{position_m: 0.2, seed: 5}");
}

}  // namespace
}  // namespace simcap
