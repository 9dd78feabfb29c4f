// Scene files that are valid: every key reaches the right field, degrees become radians, paths
// resolve against the scene's folder or the shipped assets, rigs match core/rig.h, defaults fill
// in what a file leaves out.
#include <gtest/gtest.h>

#include <numbers>

#include "core/atomic_file.h"
#include "core/rig.h"
#include "models/shipped_assets.h"
#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::TempDir;
using simcap::testing::write_scene;

constexpr double kPi = std::numbers::pi;

// A scene needs a frame count when it has no actors; these tests are about other sections.
const char* kFrames = "render: {frames: 10}\n";

TEST(SceneLoader, RoomColoursAndTextures) {
  TempDir dir;
  write_text_atomic(dir / "tex" / "floor.png", "not read by the loader");
  write_text_atomic(dir / "wall.png", "not read by the loader");
  const auto path = write_scene(dir.path(), std::string(kFrames) + R"(
room:
  size: [5, 2.5, 6]
  floor_color: "#ff8000"
  wall_color: [0.25, 0.5, 1]
  floor_texture: tex/floor.png
  wall_texture: wall.png
)");
  const Scene s = load_scene(path);
  EXPECT_EQ(s.room.size, Eigen::Vector3d(5, 2.5, 6));
  EXPECT_EQ(s.room.floor_color, Rgb(1.0f, 128 / 255.0f, 0.0f));
  EXPECT_EQ(s.room.wall_color, Rgb(0.25f, 0.5f, 1.0f));
  EXPECT_EQ(s.room.floor_texture, dir / "tex" / "floor.png");
  EXPECT_EQ(s.room.wall_texture, dir / "wall.png");
  EXPECT_TRUE(s.room.floor_texture.is_absolute());
  EXPECT_EQ(s.source, path);
}

TEST(SceneLoader, DefaultsFillInMissingSections) {
  TempDir dir;
  const Scene s = load_scene(write_scene(dir.path(), kFrames));
  const Room room;
  EXPECT_EQ(s.room.size, room.size);
  EXPECT_EQ(s.room.floor_color, room.floor_color);
  EXPECT_TRUE(s.occluders.empty());
  ASSERT_EQ(s.lights.size(), 1u);  // no 'lights' key: one default light
  EXPECT_EQ(s.lights[0].kind, Light::Kind::directional);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_NEAR(s.lights[0].direction.norm(), 1.0, 1e-15);
  EXPECT_EQ(s.ambient, 0.3);
  // Default rig: four corner cameras 0.1 m in from the walls at 2.5 m, looking at (0, 1, 0).
  const auto expected = corner_rig(4, 4, 2.5, 0.1, {0, 1, 0}, ImageSpec{});
  ASSERT_EQ(s.cameras.size(), 4u);
  for (int i = 0; i < 4; ++i) testing::expect_cameras_equal(s.cameras[i], expected[i], 0);
  EXPECT_EQ(s.render.fps, 30.0);
  EXPECT_EQ(s.render.frame_count, 10);
  EXPECT_EQ(s.render.seed, 1u);
  EXPECT_EQ(s.noise.rgb_sigma, 0.0);
}

TEST(SceneLoader, EmptyListsMeanNone) {
  TempDir dir;
  const Scene s =
      load_scene(write_scene(dir.path(), std::string(kFrames) + "lights: []\noccluders: []\n"));
  EXPECT_TRUE(s.lights.empty());
  EXPECT_TRUE(s.occluders.empty());
}

TEST(SceneLoader, Occluders) {
  TempDir dir;
  write_text_atomic(dir / "chair.obj", "v 0 0 0\n");
  const auto path = write_scene(dir.path(), std::string(kFrames) + R"(
occluders:
  - {type: box, name: table, position: [1, 0, -0.5], size: [1.2, 0.75, 0.6], yaw_deg: 90}
  - {type: cylinder, position: [-1, 0, 0], diameter: 0.3, height: 2.9, color: "#102030"}
  - {type: mesh, name: chair, mesh: chair.obj, scale: 0.01}
)");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.occluders.size(), 3u);
  const Occluder &box = s.occluders[0], &cyl = s.occluders[1], &mesh = s.occluders[2];
  EXPECT_EQ(box.kind, Occluder::Kind::box);
  EXPECT_EQ(box.name, "table");
  EXPECT_EQ(box.position, Eigen::Vector3d(1, 0, -0.5));
  EXPECT_EQ(box.size, Eigen::Vector3d(1.2, 0.75, 0.6));
  EXPECT_NEAR(box.yaw_rad, kPi / 2, 1e-15);
  EXPECT_EQ(cyl.kind, Occluder::Kind::cylinder);
  EXPECT_EQ(cyl.name, "occluder1");
  EXPECT_EQ(cyl.size, Eigen::Vector3d(0.3, 2.9, 0.3));
  EXPECT_EQ(cyl.color, Rgb(16 / 255.0f, 32 / 255.0f, 48 / 255.0f));
  EXPECT_EQ(mesh.kind, Occluder::Kind::mesh);
  EXPECT_EQ(mesh.mesh, dir / "chair.obj");
  EXPECT_EQ(mesh.mesh_scale, 0.01);
}

TEST(SceneLoader, Lights) {
  TempDir dir;
  const auto path = write_scene(dir.path(), std::string(kFrames) + R"(
ambient: 0.1
lights:
  - {type: directional, direction: [0, -2, 0], intensity: 1.5, shadows: false}
  - {type: point, position: [0.5, 2.8, -1], intensity: 2}
)");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].direction, Eigen::Vector3d(0, -1, 0));  // normalized
  EXPECT_EQ(s.lights[0].intensity, 1.5);
  EXPECT_FALSE(s.lights[0].shadows);
  EXPECT_EQ(s.lights[1].kind, Light::Kind::point);
  EXPECT_EQ(s.lights[1].position, Eigen::Vector3d(0.5, 2.8, -1));
  EXPECT_TRUE(s.lights[1].shadows);
  EXPECT_EQ(s.ambient, 0.1);
}

TEST(SceneLoader, RingRigMatchesRingRig) {
  TempDir dir;
  const auto path = write_scene(dir.path(), std::string(kFrames) + R"(
room: {size: [8, 3, 8]}
rig:
  type: ring
  count: 6
  radius: 3.5
  height: 2.2
  target: [0.5, 1.1, -0.25]
  resolution: [800, 600]
  hfov_deg: 50
  distortion: [-0.1, 0.01, 0.001, -0.002, 0]
)");
  const Scene s = load_scene(path);
  auto expected = ring_rig(6, {0.5, 1.1, -0.25}, 3.5, 2.2, ImageSpec{800, 600, 50 * kPi / 180});
  ASSERT_EQ(s.cameras.size(), 6u);
  for (int i = 0; i < 6; ++i) {
    expected[i].dist << -0.1, 0.01, 0.001, -0.002, 0;
    testing::expect_cameras_equal(s.cameras[i], expected[i], 1e-12);
  }
  EXPECT_NEAR(s.cameras[0].hfov(), 50 * kPi / 180, 1e-12);
}

TEST(SceneLoader, CornerRigUsesTheRoomAndFocalLengths) {
  TempDir dir;
  const auto path = write_scene(dir.path(), std::string(kFrames) + R"(
room: {size: [6, 3, 5]}
rig: {type: corners, count: 4, height: 2.7, inset: 0.3, fx: 500, fy: 510, cx: 300}
)");
  const Scene s = load_scene(path);
  const auto expected = corner_rig(6, 5, 2.7, 0.3, {0, 1, 0}, ImageSpec{});
  ASSERT_EQ(s.cameras.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    EXPECT_LE((s.cameras[i].R - expected[i].R).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_LE((s.cameras[i].t - expected[i].t).cwiseAbs().maxCoeff(), 1e-15);
    Eigen::Matrix3d K;
    K << 500, 0, 300, 0, 510, 239.5, 0, 0, 1;  // cy defaults to the image centre
    EXPECT_EQ(s.cameras[i].K, K);
  }
  EXPECT_NEAR(s.cameras[0].centre().x(), 2.7, 1e-12);
  EXPECT_NEAR(s.cameras[0].centre().z(), 2.2, 1e-12);
}

TEST(SceneLoader, ExplicitCamerasByLookAtAndByExtrinsics) {
  TempDir dir;
  const auto path = write_scene(dir.path(), std::string(kFrames) + R"(
rig:
  type: explicit
  resolution: [320, 240]
  hfov_deg: 70
  cameras:
    - name: front
      eye: [0, 1.5, 1.9]
      target: [0, 1, 0]
    - eye: [1.5, 2, -1.5]
      target: [0, 1, 0]
      up: [0, 1, 0.1]
      resolution: [640, 480]
      K: [[600, 0, 320], [0, 600, 240], [0, 0, 1]]
      distortion: [0.1, 0, 0, 0, 0]
    - name: side
      R: [[0, 0, -1], [0, -1, 0], [-1, 0, 0]]
      t: [0, 1, 1.8]
)");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.cameras.size(), 3u);
  testing::expect_cameras_equal(
      s.cameras[0], Camera::look_at("front", 320, 240, 70 * kPi / 180, {0, 1.5, 1.9}, {0, 1, 0}),
      1e-12);
  Camera second = Camera::look_at("cam01", 640, 480, 1.0, {1.5, 2, -1.5}, {0, 1, 0}, {0, 1, 0.1});
  second.K << 600, 0, 320, 0, 600, 240, 0, 0, 1;
  second.dist[0] = 0.1;
  testing::expect_cameras_equal(s.cameras[1], second, 1e-12);
  const Camera& side = s.cameras[2];
  EXPECT_EQ(side.name, "side");
  EXPECT_EQ(side.width, 320);
  EXPECT_NEAR(side.hfov(), 70 * kPi / 180, 1e-12);  // rig-level intrinsics are the default
  // R maps world -x to the optical axis: the camera at x = +1.8 looks towards -x.
  EXPECT_LE((side.centre() - Eigen::Vector3d(1.8, 1, 0)).norm(), 1e-12);
  EXPECT_TRUE(side.in_frustum({0, 1, 0}));
}

TEST(SceneLoader, ActorsAndMotions) {
  TempDir dir;
  write_text_atomic(dir / "clips" / "walk.bvh", "HIERARCHY\n");
  const auto path = write_scene(dir.path(), R"(
actors:
  - name: alice
    height: 1.62
    girth: 1.1
    proportions: {hip_height: 0.52, forearm: 0.15, shoulder_rise: -0.01}
    colors: {shirt: "#ff0000", hair: [0.9, 0.8, 0.1]}
    motion: {bvh: clips/walk.bvh, units: 0.0254}
    offset: [0.5, 0, -1]
    yaw_deg: -90
    time_offset: 0.25
  - motion: {bvh: asset:cmu_131_01_start_walk_stop.bvh, units: auto}
  - motion: {procedural: walk_path, duration: 3, speed: 0.9, radius: 1.5}
  - motion: {procedural: turn, turn_deg: 90}
  - motion: {procedural: arm_gesture, gesture: ask, duration: 5.5}
)");
  const Scene s = load_scene(path);
  ASSERT_EQ(s.actors.size(), 5u);
  const Actor& a = s.actors[0];
  EXPECT_EQ(a.name, "alice");
  EXPECT_EQ(a.body.parameters.height, 1.62);
  EXPECT_EQ(a.body.shape.girth, 1.1);
  EXPECT_EQ(a.body.parameters.proportions.hip_height, 0.52);
  EXPECT_EQ(a.body.parameters.proportions.forearm, 0.15);
  EXPECT_EQ(a.body.parameters.proportions.shoulder_rise, -0.01);
  EXPECT_EQ(a.body.parameters.proportions.knee_height, BodyProportions{}.knee_height);
  const Actor defaults;
  EXPECT_EQ(a.colors[static_cast<int>(MaterialRegion::skin)],
            defaults.colors[static_cast<int>(MaterialRegion::skin)]);
  EXPECT_EQ(a.colors[static_cast<int>(MaterialRegion::shirt)], Rgb(1, 0, 0));
  EXPECT_EQ(a.colors[static_cast<int>(MaterialRegion::hair)], Rgb(0.9f, 0.8f, 0.1f));
  EXPECT_EQ(a.motion.bvh, dir / "clips" / "walk.bvh");
  EXPECT_EQ(a.motion.bvh_metres_per_unit, 0.0254);
  EXPECT_EQ(a.offset, Eigen::Vector3d(0.5, 0, -1));
  EXPECT_NEAR(a.yaw_rad, -kPi / 2, 1e-15);
  EXPECT_EQ(a.time_offset_s, 0.25);

  EXPECT_EQ(s.actors[1].name, "actor1");
  EXPECT_EQ(s.actors[1].motion.bvh,
            SIMCAP_SOURCE_DIR "/models/assets/cmu_131_01_start_walk_stop.bvh");
  EXPECT_EQ(s.actors[1].motion.bvh_metres_per_unit, 0.0);
  EXPECT_EQ(s.actors[1].body.parameters.height, BodyParameters{}.height);

  const ProceduralSpec& p = s.actors[2].motion.procedural;
  EXPECT_TRUE(s.actors[2].motion.bvh.empty());
  EXPECT_EQ(p.kind, "walk_path");
  EXPECT_EQ(p.duration_s, 3.0);
  EXPECT_EQ(p.speed_m_s, 0.9);
  EXPECT_EQ(p.path_radius, 1.5);
  EXPECT_EQ(s.actors[3].motion.procedural.kind, "turn");
  EXPECT_EQ(s.actors[3].motion.procedural.turn_degrees, 90.0);
  EXPECT_EQ(s.actors[3].motion.procedural.duration_s, ProceduralSpec{}.duration_s);
  EXPECT_EQ(s.actors[4].motion.procedural.kind, "arm_gesture");
  EXPECT_EQ(s.actors[4].motion.procedural.gesture, "ask");
}

TEST(SceneLoader, RenderAndNoise) {
  TempDir dir;
  const auto path = write_scene(dir.path(), R"(
render:
  fps: 60
  first_frame: 12
  frames: 100
  samples_per_pixel: 4
  seed: 18446744073709551615
  normals: true
noise: {rgb_sigma: 2.5, depth_sigma: 0.004}
)");
  const Scene s = load_scene(path);
  EXPECT_EQ(s.render.fps, 60.0);
  EXPECT_EQ(s.render.first_frame, 12);
  EXPECT_EQ(s.render.frame_count, 100);
  EXPECT_EQ(s.render.samples_per_pixel, 4);
  EXPECT_EQ(s.render.seed, 18446744073709551615ull);
  EXPECT_TRUE(s.render.normals);
  EXPECT_EQ(s.noise.rgb_sigma, 2.5);
  EXPECT_EQ(s.noise.depth_sigma_m, 0.004);
}

TEST(SceneLoader, FramesAllIsTheDefaultWithActors) {
  TempDir dir;
  const Scene s = load_scene(
      write_scene(dir.path(), "actors: [{motion: {procedural: stand}}]\nrender: {frames: all}\n"));
  EXPECT_EQ(s.render.frame_count, -1);
}

TEST(SceneLoader, ScenePathRelativeToTheWorkingFolderResolves) {
  TempDir dir;
  write_text_atomic(dir / "sub" / "m.bvh", "HIERARCHY\n");
  write_scene(dir / "sub", "actors: [{motion: {bvh: m.bvh}}]\n");
  const auto cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir.path());
  const Scene s = load_scene("sub/scene.yaml");
  std::filesystem::current_path(cwd);
  EXPECT_EQ(s.actors[0].motion.bvh, dir / "sub" / "m.bvh");
}

TEST(SceneLoader, ShippedScenePathFindsTheDefault) {
  EXPECT_EQ(shipped_scene_path("studio4"), SIMCAP_SOURCE_DIR "/scenes/studio4.yaml");
  try {
    shipped_scene_path("nope");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("studio4"), std::string::npos) << e.what();
  }
}

TEST(SceneLoader, AssetPathsAreWrittenBackWithThePrefix) {
  const auto clip = asset_dir() / "cmu_131_01_start_walk_stop.bvh";
  EXPECT_EQ(asset_path_text(clip), "asset:cmu_131_01_start_walk_stop.bvh");
  EXPECT_EQ(resolve_asset_path("asset:cmu_131_01_start_walk_stop.bvh", "/elsewhere"), clip);
  EXPECT_EQ(asset_path_text("/data/clip.bvh"), "/data/clip.bvh");
  EXPECT_EQ(resolve_asset_path("../b/c.png", "/a/s"), std::filesystem::path("/a/b/c.png"));
}

TEST(SceneLoader, ActorLimitsAreAUrdfTheLoaderChecks) {
  TempDir dir;
  const auto ok = testing::write_scene(
      dir.path(),
      "actors:\n  - motion: {procedural: stand}\n    limits: asset:humanoid_limits.urdf\n");
  const Scene s = load_scene(ok);
  EXPECT_EQ(s.actors[0].limits, asset_dir() / "humanoid_limits.urdf");
  EXPECT_NE(scene_to_yaml(s).find("limits: \"asset:humanoid_limits.urdf\""), std::string::npos);
  write_text_atomic(dir / "bad.urdf", "<robot name=\"x\"><joint");
  const auto bad = testing::write_scene(
      dir.path(), "actors:\n  - motion: {procedural: stand}\n    limits: bad.urdf\n");
  const std::string e = testing::load_error(bad);
  EXPECT_NE(e.find(":3: actors[0].limits: "), std::string::npos) << e;
  EXPECT_NE(e.find("bad.urdf: not a valid URDF"), std::string::npos) << e;
}

}  // namespace
}  // namespace simcap
