// scene_to_yaml: the resolved scene reads back as the same scene (to 1e-12), the text is the same
// on every run, every default is written out, and cameras become an explicit rig.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "core/rig.h"
#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::expect_scenes_equal;
using simcap::testing::TempDir;
using simcap::testing::write_scene;

// Every feature of the schema at a non-default value.
const char* kRichScene = R"(
room:
  size: [6.5, 2.75, 5.25]
  floor_color: "#203040"
  wall_color: [0.1, 0.2, 0.3]
  floor_texture: floor.png
occluders:
  - {type: box, name: crate, position: [1, 0, -1], size: [0.5, 0.4, 0.3], yaw_deg: 33.3}
  - {type: cylinder, position: [-1, 0.2, 1], diameter: 0.35, height: 2.2, color: [0.3, 0.3, 0.3]}
  - {type: mesh, name: statue, mesh: statue.obj, scale: 0.001, position: [2, 0, 2], yaw_deg: -10}
lights:
  - {type: directional, direction: [0.3, -1, 0.2], intensity: 0.7, shadows: false}
  - {type: point, position: [0, 2.5, 0], intensity: 1.3}
ambient: 0.17
rig:
  type: explicit
  resolution: [800, 600]
  hfov_deg: 55.5
  distortion: [-0.12, 0.03, 0.0005, -0.0007, 0.001]
  cameras:
    - {name: north, eye: [0.3, 2.1, -2.4], target: [0, 1, 0.1]}
    - {name: south, eye: [-0.2, 1.7, 2.5], target: [0.1, 0.9, 0], fx: 612.25, fy: 611.5, cx: 401.2}
actors:
  - name: bob
    height: 1.83
    girth: 1.2
    proportions: {knee_height: 0.29, hip_joint_spacing: 0.55, shoulder_rise: 0.03}
    colors: {skin: [0.7, 0.5, 0.4], trousers: "#112233"}
    motion: {bvh: walk.bvh, units: 0.0254}
    offset: [0.1, 0.02, -0.3]
    yaw_deg: 123.4
    time_offset: 0.4
  - motion: {bvh: walk.bvh}
  - motion: {procedural: walk_path, duration: 2.5, speed: 0.8, radius: 1.25}
  - motion: {procedural: turn, turn_deg: -45}
  - motion: {procedural: jumps, duration: 5, count: 2, distance: 0.6, height: 0.2}
  - motion: {procedural: turnaround, duration: 5, speed: 1.0, distance: 1.25}
  - motion: {procedural: squat, count: 2, depth: 0.25}
  - motion: {procedural: arms_cross, count: 1}
  - motion: {procedural: side_steps, duration: 3, count: 1, distance: -0.625}
  - motion: {procedural: bend_forward, count: 1}
  - motion: {procedural: kick, duration: 3.5, count: 1, height: 0.6}
  - motion: {procedural: arm_swings, frequency: 1.25, amplitude: 45}
render:
  fps: 24
  first_frame: 3
  frames: 17
  samples_per_pixel: 2
  seed: 987654321987654321
  normals: true
noise: {rgb_sigma: 1.5, depth_sigma: 0.002}
)";

std::filesystem::path rich_scene(const TempDir& dir) {
  write_text_atomic(dir / "floor.png", "x");
  write_text_atomic(dir / "statue.obj", "v 0 0 0\n");
  write_text_atomic(dir / "walk.bvh", "HIERARCHY\n");
  return write_scene(dir.path(), kRichScene);
}

TEST(SceneWriter, RoundTripOfEveryFeature) {
  TempDir dir;
  const Scene a = load_scene(rich_scene(dir));
  const std::string text = scene_to_yaml(a);
  TempDir elsewhere;  // absolute paths keep the resolved file valid in another folder
  const Scene b = load_scene(write_scene(elsewhere.path(), text, "resolved.yaml"));
  expect_scenes_equal(a, b);
  EXPECT_EQ(scene_to_yaml(b), text);
}

TEST(SceneWriter, RoundTripOfProgrammaticCameras) {
  // Cameras straight from rig.h with distortion and a shifted principal point: the explicit
  // rig written for them must reproduce K, dist, R, t and the image size.
  TempDir dir;
  Scene a = load_scene(write_scene(dir.path(), "render: {frames: 4}\nroom: {size: [9, 4, 9]}\n"));
  a.cameras = ring_rig(5, {0.3, 1.2, -0.4}, 3.7, 2.9, ImageSpec{1280, 720, 1.1});
  a.cameras[2].dist << -0.2, 0.05, 0.001, -0.002, 0.01;
  a.cameras[3].K(0, 2) = 633.125;
  a.cameras[4].name = "overhead";
  const Scene b = load_scene(write_scene(dir.path(), scene_to_yaml(a), "resolved.yaml"));
  expect_scenes_equal(a, b);
}

TEST(SceneWriter, WritesEveryDefaultAndAnExplicitRig) {
  TempDir dir;
  const Scene s =
      load_scene(write_scene(dir.path(), "actors: [{motion: {procedural: stand}}]\nrig: {}\n"));
  const YAML::Node y = YAML::Load(scene_to_yaml(s));
  for (const char* key :
       {"room", "occluders", "lights", "ambient", "rig", "actors", "render", "noise"}) {
    EXPECT_TRUE(y[key].IsDefined()) << key;
  }
  EXPECT_TRUE(y["occluders"].IsSequence());
  EXPECT_EQ(y["occluders"].size(), 0u);
  EXPECT_EQ(y["rig"]["type"].as<std::string>(), "explicit");
  ASSERT_EQ(y["rig"]["cameras"].size(), 4u);
  for (const char* key : {"name", "resolution", "K", "distortion", "R", "t"}) {
    EXPECT_TRUE(y["rig"]["cameras"][0][key].IsDefined()) << key;
  }
  const YAML::Node actor = y["actors"][0];
  for (const char* key : {"name", "height", "girth", "proportions", "colors", "motion", "offset",
                          "yaw_deg", "time_offset"}) {
    EXPECT_TRUE(actor[key].IsDefined()) << key;
  }
  EXPECT_EQ(actor["proportions"].size(), 14u);
  EXPECT_EQ(actor["colors"].size(), 5u);
  EXPECT_EQ(actor["motion"]["procedural"].as<std::string>(), "stand");
  EXPECT_EQ(actor["motion"]["duration"].as<double>(), ProceduralSpec{}.duration_s);
  EXPECT_EQ(y["render"]["frames"].as<std::string>(), "all");
  EXPECT_EQ(y["render"]["seed"].as<std::string>(), "1");
  EXPECT_EQ(y["render"]["normals"].as<bool>(), false);
}

TEST(SceneWriter, ShippedAssetsAreWrittenWithTheAssetPrefix) {
  TempDir dir;
  const Scene s = load_scene(
      write_scene(dir.path(), "actors: [{motion: {bvh: asset:cmu_131_01_start_walk_stop.bvh}}]\n"));
  const YAML::Node y = YAML::Load(scene_to_yaml(s));
  EXPECT_EQ(y["actors"][0]["motion"]["bvh"].as<std::string>(),
            "asset:cmu_131_01_start_walk_stop.bvh");
  EXPECT_EQ(y["actors"][0]["motion"]["units"].as<std::string>(), "auto");
}

TEST(SceneWriter, NamesThatLookLikeOtherYamlTypesStayText) {
  TempDir dir;
  Scene s = load_scene(write_scene(dir.path(), "render: {frames: 2}\n"));
  s.cameras[0].name = "true";
  s.cameras[1].name = "null";
  s.cameras[2].name = "12";
  s.cameras[3].name = "# not a comment: really";
  const Scene back = load_scene(write_scene(dir.path(), scene_to_yaml(s), "resolved.yaml"));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(back.cameras[i].name, s.cameras[i].name);
}

}  // namespace
}  // namespace simcap
