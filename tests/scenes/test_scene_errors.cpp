// Bad scene files: each error names the file, the line, the key path and what was expected.
#include <gtest/gtest.h>

#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::load_error;
using simcap::testing::TempDir;
using simcap::testing::write_scene;

struct BadCase {
  const char* yaml;
  int line;              // of the offending key or value
  const char* key_path;  // as the message names it
  const char* expected;  // part of the explanation
};

class BadScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScene, NamesFileLineKeyAndExpectation) {
  const BadCase& c = GetParam();
  TempDir dir;
  const auto path = write_scene(dir.path(), c.yaml);
  const std::string msg = load_error(path);
  const std::string where = path.string() + ":" + std::to_string(c.line) + ": " + c.key_path + ": ";
  EXPECT_EQ(msg.rfind(where, 0), 0u) << "message: " << msg << "\nexpected start: " << where;
  EXPECT_NE(msg.find(c.expected), std::string::npos) << "message: " << msg;
}

// Sections are read in file-schema order (room, occluders, lights, ambient, rig, actors, render,
// noise), so a case fails on its one bad entry before a scene without actors is refused for
// lacking render.frames; cases after that point give the frame count.
INSTANTIATE_TEST_SUITE_P(
    Cases, BadScene,
    ::testing::Values(
        BadCase{"render: {frames: 5}\nbogus: 1\n", 2, "bogus",
                "unknown key (expected one of: room, occluders"},
        BadCase{"room:\n  size: [4, 3]\n", 2, "room.size", "a list of 3 items, got 2"},
        BadCase{"room:\n  size: [4, -3, 4]\n", 2, "room.size[1]", "a number in (0, 1000]"},
        BadCase{"room:\n  size: [4, abc, 4]\n", 2, "room.size[1]", "got 'abc'"},
        BadCase{"room:\n  size: 4\n", 2, "room.size", "expected a list of 3 items"},
        BadCase{"room:\n  floor_color: [1.5, 0, 0]\n", 2, "room.floor_color[0]",
                "a number in [0, 1]"},
        BadCase{"room:\n  wall_color: #ff0000\n", 2, "room.wall_color", "in quotes"},
        BadCase{"room:\n  wall_color: \"#ff00\"\n", 2, "room.wall_color", "#rrggbb"},
        BadCase{"room:\n  floor_texture: missing.png\n", 2, "room.floor_texture",
                "missing.png' does not exist"},
        BadCase{"room:\n  colour: [1, 1, 1]\n", 2, "room.colour", "unknown key"},
        BadCase{"room: [1, 2]\n", 1, "room", "expected a map of keys, got a list"},
        BadCase{"occluders:\n  - {type: box}\n  - {type: sphere}\n", 3, "occluders[1].type",
                "one of box, cylinder or mesh"},
        BadCase{"occluders:\n  - {position: [0, 0, 0]}\n", 2, "occluders[0]", "missing key 'type'"},
        BadCase{"occluders:\n  - {type: box, diameter: 1}\n", 2, "occluders[0].diameter",
                "unknown key"},
        BadCase{"occluders:\n  - {type: cylinder, diameter: 0}\n", 2, "occluders[0].diameter",
                "in (0, 1000]"},
        BadCase{"occluders:\n  - {type: mesh}\n", 2, "occluders[0]", "missing key 'mesh'"},
        BadCase{"occluders:\n  - {type: box, name: a}\n  - {type: box, name: a}\n", 3,
                "occluders[1]", "duplicate occluder name a"},
        BadCase{"occluders:\n  - {type: box, yaw_deg: .inf}\n", 2, "occluders[0].yaw_deg",
                "a number"},
        BadCase{"lights:\n  - {type: point, direction: [0, -1, 0]}\n", 2, "lights[0].direction",
                "unknown key"},
        BadCase{"lights:\n  - {type: directional, direction: [0, 0, 0]}\n", 2,
                "lights[0].direction", "non-zero"},
        BadCase{"lights:\n  - {type: point, intensity: -1}\n", 2, "lights[0].intensity",
                "in [0, 1000]"},
        BadCase{"lights:\n  - {type: point, shadows: maybe}\n", 2, "lights[0].shadows",
                "true or false"},
        BadCase{"ambient: 2\n", 1, "ambient", "in [0, 1]"},
        BadCase{"rig:\n  type: circle\n", 2, "rig.type", "one of corners, ring or explicit"},
        BadCase{"rig:\n  type: ring\n  count: 2.5\n", 3, "rig.count", "an integer in [1, 1000]"},
        BadCase{"rig:\n  type: ring\n  count: 010x\n", 3, "rig.count", "an integer"},
        BadCase{"rig:\n  type: ring\n  radius: 0\n", 3, "rig.radius", "in (0, 1000]"},
        BadCase{"rig:\n  type: ring\n  radius: 5\n", 3, "rig.radius", "outside the room"},
        BadCase{"rig:\n  type: corners\n  height: 3.5\n", 3, "rig.height", "outside the room"},
        BadCase{"rig:\n  type: corners\n  inset: 0\n", 3, "rig.inset", "a number in (0, 1000]"},
        BadCase{"rig:\n  type: corners\n  count: 6\n", 3, "rig.count", "exactly 4 cameras"},
        BadCase{"rig:\n  type: corners\n  inset: 2\n", 3, "rig.inset", "less than half"},
        BadCase{"rig:\n  type: corners\n  radius: 2\n", 3, "rig.radius",
                "unknown key (expected one of: type, resolution, hfov_deg"},
        BadCase{"rig:\n  resolution: [640, 0]\n", 2, "rig.resolution[1]",
                "an integer in [1, 16384]"},
        BadCase{"rig:\n  resolution: [100000, 100000]\n", 2, "rig.resolution[0]",
                "an integer in [1, 16384] (16384: simcap's largest image side), got '100000'"},
        BadCase{"rig:\n  resolution: [16384, 16384]\n", 2, "rig.resolution",
                "16384x16384 pixels is more than the 67108864 (8192x8192) simcap allows"},
        BadCase{"rig:\n  hfov_deg: 180\n", 2, "rig.hfov_deg", "in (0, 180)"},
        BadCase{"rig:\n  hfov_deg: 60\n  fx: 500\n  fy: 500\n", 3, "rig.fx", "one way only"},
        BadCase{"rig:\n  fx: 500\n", 2, "rig.fx", "fx and fy must be given together"},
        BadCase{"rig:\n  distortion: [0, 0, 0, 0]\n", 2, "rig.distortion", "5 items"},
        BadCase{"rig:\n  type: explicit\n", 1, "rig", "missing key 'cameras'"},
        BadCase{"rig:\n  type: explicit\n  cameras: []\n", 3, "rig.cameras",
                "a list of 1 to 1000 items, got 0"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n    - {eye: [0, 1, 1]}\n", 4, "rig.cameras[0]",
                "needs both 'eye' and 'target'"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n    - {name: a}\n", 4, "rig.cameras[0]",
                "needs a pose"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n    - {eye: [0, 1, 1], target: [0, 1, 1]}\n",
                4, "rig.cameras[0].target", "must differ from the eye"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n    - {eye: [0, 2, 0], target: [0, 1, 0]}\n",
                4, "rig.cameras[0].target", "parallel to the up vector"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n"
                "    - {R: [[1, 0, 0], [0, 1, 0], [0, 0, 2]], t: [0, 0, 0]}\n",
                4, "rig.cameras[0].R", "rotation matrix"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n"
                "    - {R: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], t: [0, -1.5, 0], eye: [0, 1, 0]}\n",
                4, "rig.cameras[0].R", "one way only"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n"
                "    - {R: [[1, 0, 0], [0, 1, 0], [0, 0, 1]], t: [0, 1.5, 0]}\n",
                4, "rig.cameras[0]", "outside the room"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n"
                "    - {eye: [0, 1, 1], target: [0, 1, 0], K: [[500, 1, 320], [0, 500, 240], "
                "[0, 0, 1]]}\n",
                4, "rig.cameras[0].K", "[[fx, 0, cx], [0, fy, cy], [0, 0, 1]]"},
        BadCase{"rig:\n  type: explicit\n  cameras:\n    - {eye: [0, 1, 1], target: [0, 1, 0]}\n"
                "    - {eye: [0, 1, -1], target: [0, 1, 0], name: cam00}\n",
                5, "rig.cameras[1]", "duplicate camera name cam00"},
        BadCase{"actors:\n  - {name: a}\n", 2, "actors[0]", "missing key 'motion'"},
        BadCase{"actors:\n  - body: {x3d: nowhere.x3d}\n", 2, "actors[0].body.x3d",
                "nowhere.x3d' does not exist"},
        BadCase{"actors:\n  - body: {obj: a.obj}\n", 2, "actors[0].body",
                "a map with one of 'x3d: <an H-Anim X3D file>' or 'mesh: <a rigged mesh>'"},
        BadCase{"actors:\n  - body: {mesh: asset:JoeSkin.x3d, joint_map: bones}\n", 2,
                "actors[0].body.joint_map", "one of auto, hanim, mixamo or vrm"},
        BadCase{"actors:\n  - body: {mesh: asset:JoeSkin.x3d, units: -2}\n", 2,
                "actors[0].body.units", "a number in (0, 1000]"},
        BadCase{"actors:\n  - body: {x3d: asset:JoeSkin.x3d}\n    height: 1.8\n", 3,
                "actors[0].height",
                "height, girth, proportions and vary shape simcap's own humanoid"},
        BadCase{"actors:\n  - motion: {procedural: fly}\n", 2, "actors[0].motion.procedural",
                "one of stand, tpose"},
        BadCase{"actors:\n  - motion: {}\n", 2, "actors[0].motion", "exactly one of 'bvh'"},
        BadCase{"actors:\n  - motion:\n      procedural: walk_path\n      speed: -1\n", 4,
                "actors[0].motion.speed", "a number in (0, 20]"},
        BadCase{"actors:\n  - motion:\n      procedural: walk_path\n      units: auto\n", 4,
                "actors[0].motion.units", "unknown key"},
        BadCase{"actors:\n  - motion:\n      procedural: jumps\n      height: 2\n", 4,
                "actors[0].motion.height", "must be in [0.05, 0.5] m, got 2"},
        BadCase{"actors:\n  - motion:\n      procedural: squat\n      height: 0.3\n", 4,
                "actors[0].motion.height", "unknown key"},
        BadCase{"actors:\n  - motion:\n      procedural: kick\n      count: 5\n", 2,
                "actors[0].motion", "the default duration of kick must be at least 8.5 s"},
        BadCase{"actors:\n  - motion: {procedural: squat, count: 2.5}\n", 2,
                "actors[0].motion.count", "an integer"},
        BadCase{"actors:\n  - motion: {procedural: turnaround, speed: 3}\n", 2,
                "actors[0].motion.speed", "must be in [0.6, 1.6] m/s"},
        BadCase{"actors:\n  - motion:\n      procedural: arm_gesture\n      gesture: shrug\n", 4,
                "actors[0].motion.gesture", "one of raise, joy, exclaim or ask"},
        BadCase{"actors:\n  - motion: {bvh: nowhere.bvh}\n", 2, "actors[0].motion.bvh",
                "does not exist"},
        BadCase{"actors:\n  - motion: {bvh: asset:nowhere.bvh}\n", 2, "actors[0].motion.bvh",
                "models/assets/nowhere.bvh' does not exist"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n    height: 3\n", 3, "actors[0].height",
                "in [0.5, 2.5]"},
        BadCase{
            "actors:\n  - motion: {procedural: stand}\n    height: 0.6\n    vary: {height: 0.5}\n",
            4, "actors[0].vary.height", "height 0.6 +- 0.5 m leaves [0.5, 2.5] m"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n    vary: {proportions: 0.1}\n"
                "    proportions: {hip_height: 0.78}\n",
                3, "actors[0].vary.proportions",
                "hip_height (0.858) must lie below shoulder_height (0.818): heights rise from the "
                "ankle to the chin, in fractions of the height with the legs 1.1 times as long"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n    colors: {cape: [1, 0, 0]}\n", 3,
                "actors[0].colors.cape", "expected one of: skin, shirt, trousers, shoes, hair"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n    proportions: {hip_height: 1.5}\n", 3,
                "actors[0].proportions.hip_height", "in (0, 1]"},
        BadCase{
            "actors:\n  - motion: {procedural: stand}\n    proportions: {shoulder_height: 0.95}\n",
            3, "actors[0].proportions", "shoulder_height (0.95) must lie below chin_height (0.87)"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n    proportions: {shoulder_rise: 0.1}\n",
                3, "actors[0].proportions.shoulder_rise", "in [-0.05, 0.05]"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n    offset: [0, 0]\n", 3,
                "actors[0].offset", "3 items"},
        BadCase{"actors:\n  - motion: {procedural: stand}\n  - motion: {procedural: stand}\n"
                "    name: actor0\n",
                3, "actors[1]", "duplicate actor name actor0"},
        BadCase{"render:\n  fps: 0\n", 2, "render.fps", "in (0, 1000]"},
        BadCase{"render:\n  frames: some\n", 2, "render.frames", "an integer in [1, "},
        BadCase{"render:\n  frames: all\n", 2, "render.frames", "without actors"},
        BadCase{"render:\n  frames: 10000000\n", 2, "render.frames",
                "an integer in [1, 1000000] (1000000: simcap's largest frame count)"},
        BadCase{"render:\n  seed: -1\n", 2, "render.seed", "an integer in [0, 2^64 - 1]"},
        BadCase{"render:\n  samples_per_pixel: 0\n", 2, "render.samples_per_pixel",
                "an integer in [1, 65536]"},
        BadCase{"render:\n  frames: 5\n  frames: 6\n", 3, "render.frames", "duplicate key"},
        BadCase{"render: {frames: 5}\nnoise:\n  depth_sigma: -0.1\n", 3, "noise.depth_sigma",
                "in [0, 10]"},
        // The capture nuisances (scenes/capture_keys.h).
        BadCase{"rig:\n  calibration_error: {rotation_deg: -1}\n", 2,
                "rig.calibration_error.rotation_deg", "in [0, 180]"},
        BadCase{"rig:\n  calibration_error: {focal_rel: 1}\n", 2, "rig.calibration_error.focal_rel",
                "in [0, 1)"},
        BadCase{"rig:\n  calibration_error: {shear: 1}\n", 2, "rig.calibration_error.shear",
                "unknown key"},
        BadCase{"rig:\n  sync: {offset_ms: [0, 1, 2]}\n", 2, "rig.sync.offset_ms",
                "one offset per camera (4), got 3"},
        BadCase{"rig:\n  sync: {offset_ms: [0, 1, 2, 3], offset_ms_sigma: 2}\n", 2,
                "rig.sync.offset_ms_sigma", "one way only"},
        BadCase{"rig:\n  sync: {seed: 2}\n", 2, "rig.sync", "offset_ms"},
        BadCase{"rig:\n  sync: {offset_ms_sigma: -2}\n", 2, "rig.sync.offset_ms_sigma",
                "in [0, 10000]"},
        BadCase{"rig:\n  readout_ms: -3\n", 2, "rig.readout_ms", "in [0, 10000]"},
        BadCase{"rig:\n  auto_exposure: sometimes\n", 2, "rig.auto_exposure", "true or false"},
        BadCase{"render:\n  frames: 2\n  shutter: 1.5\n", 3, "render.shutter", "in [0, 1]"},
        BadCase{"render:\n  frames: 2\n  shutter: 0.5\n", 3, "render.shutter",
                "samples_per_pixel > 1"},
        BadCase{"lights:\n  - type: point\n    keyframes: [{intensity: 1}]\n", 3,
                "lights[0].keyframes[0]", "missing key 'time'"},
        BadCase{"lights:\n  - type: point\n    keyframes:\n      - {time: 1, intensity: 1}\n"
                "      - {time: 1, intensity: 2}\n",
                5, "lights[0].keyframes[1].time", "must increase"},
        BadCase{"lights:\n  - type: point\n    keyframes: [{time: 1, direction: [0, -1, 0]}]\n", 3,
                "lights[0].keyframes[0].direction", "unknown key"},
        BadCase{"lights:\n  - type: point\n    keyframes: [{time: 1}]\n", 3,
                "lights[0].keyframes[0]", "a value besides its time"},
        BadCase{"lights:\n  - type: directional\n    keyframes:\n"
                "      - {time: 0, direction: [0, -1, 0]}\n"
                "      - {time: 1, direction: [0, 1, 0]}\n",
                5, "lights[0].keyframes[1].direction", "opposite"}));

TEST(SceneErrors, DuplicateTopLevelSectionIsRejected) {
  TempDir dir;
  const auto path = write_scene(dir.path(), "render: {frames: 5}\nrender: {frames: 6}\n");
  EXPECT_NE(load_error(path).find(":2: render: duplicate key"), std::string::npos)
      << load_error(path);
}

TEST(SceneErrors, SyntaxErrorNamesFileAndLine) {
  TempDir dir;
  const auto path = write_scene(dir.path(), "render:\n  fps: [30\nrig: {}\n");
  const std::string msg = load_error(path);
  EXPECT_EQ(msg.rfind(path.string() + ":", 0), 0u) << msg;
  EXPECT_NE(msg.find("not valid YAML"), std::string::npos) << msg;
}

TEST(SceneErrors, MissingFileIsNamed) {
  TempDir dir;
  const std::string msg = load_error(dir / "absent.yaml");
  EXPECT_NE(msg.find("absent.yaml"), std::string::npos) << msg;
}

TEST(SceneErrors, TopLevelMustBeAMap) {
  TempDir dir;
  const auto path = write_scene(dir.path(), "- 1\n- 2\n");
  EXPECT_NE(load_error(path).find("(top level): expected a map of keys, got a list"),
            std::string::npos)
      << load_error(path);
}

}  // namespace
}  // namespace simcap
