// Overrides ("key.path=value") change the YAML before validation: they reach nested keys and list
// items, create missing sections, replace whole lists; a bad override, or a bad value it brings,
// is an error that names the override.
#include <gtest/gtest.h>

#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::load_error;
using simcap::testing::TempDir;
using simcap::testing::write_scene;

const char* kScene = R"(
room: {size: [8, 3, 8]}
occluders:
  - {type: box, size: [1, 1, 1]}
  - {type: cylinder}
rig: {type: ring, count: 8, radius: 3}
actors:
  - motion: {procedural: walk_path, speed: 1.2}
  - motion: {procedural: stand}
)";

TEST(SceneOverrides, ChangeNestedKeysAndListItems) {
  TempDir dir;
  const auto path = write_scene(dir.path(), kScene);
  const Scene s = load_scene(
      path, {"rig.count=6", "render.frames=30", "occluders=[]", "actors[0].motion.speed=1.5",
             "actors[1].yaw_deg=90", "room.floor_color=\"#000000\"", "noise={rgb_sigma: 2}"});
  EXPECT_EQ(s.cameras.size(), 6u);
  EXPECT_EQ(s.render.frame_count, 30);  // 'render' was absent: created
  EXPECT_TRUE(s.occluders.empty());
  EXPECT_EQ(s.actors[0].motion.procedural.speed_m_s, 1.5);
  EXPECT_NEAR(s.actors[1].yaw_rad, std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(s.room.floor_color, Rgb(0, 0, 0));
  EXPECT_EQ(s.room.size.x(), 8.0);  // siblings of an overridden key stay
  EXPECT_EQ(s.noise.rgb_sigma, 2.0);
}

TEST(SceneOverrides, LaterOverridesWin) {
  TempDir dir;
  const Scene s = load_scene(write_scene(dir.path(), kScene), {"rig.count=5", "rig.count=3"});
  EXPECT_EQ(s.cameras.size(), 3u);
}

TEST(SceneOverrides, OverrideIntoAnEmptyFile) {
  TempDir dir;
  const Scene s = load_scene(write_scene(dir.path(), ""),
                             {"render.frames=7", "rig.type=ring", "rig.radius=1.5"});
  EXPECT_EQ(s.render.frame_count, 7);
  EXPECT_EQ(s.cameras.size(), 8u);
}

struct BadOverride {
  const char* text;
  const char* expected;  // part of the message after "override '<text>': "
};

class BadOverrides : public ::testing::TestWithParam<BadOverride> {};

TEST_P(BadOverrides, NameTheOverride) {
  TempDir dir;
  const auto path = write_scene(dir.path(), kScene);
  const BadOverride& c = GetParam();
  const std::string msg = load_error(path, {"render.frames=10", c.text});
  const std::string start = path.string() + ": override '" + c.text + "': ";
  EXPECT_EQ(msg.rfind(start, 0), 0u) << "message: " << msg << "\nexpected start: " << start;
  EXPECT_NE(msg.find(c.expected), std::string::npos) << "message: " << msg;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadOverrides,
    ::testing::Values(
        // Malformed overrides.
        BadOverride{"rig.count", "expected key.path=value"},
        BadOverride{"=6", "expected a key path"},
        BadOverride{"rig..count=6", "expected a key path"},
        BadOverride{"rig.count.=6", "expected a key path"},
        BadOverride{"actors[x].name=a", "expected a key path"},
        BadOverride{"actors[0.name=a", "expected a key path"},
        BadOverride{"rig.count=[1, 2", "the value is not valid YAML"},
        BadOverride{"actors[2].name=a", "index 2 is out of range: 'actors' has 2 items"},
        BadOverride{"rig[0]=1", "'rig' is a map, not a list"},
        BadOverride{"lights[0].type=point", "'lights' is absent, not a list"},
        BadOverride{"rig.count.x=1", "'rig.count' is a single value, not a map"},
        BadOverride{"actors.name=a", "'actors' is a list, not a map"},
        // Well-formed overrides whose values fail validation.
        BadOverride{"rig.count=six", "rig.count: expected an integer in [1, 1000], got 'six'"},
        BadOverride{"rig.count=", "rig.count: expected an integer in [1, 1000], got nothing"},
        BadOverride{"rig.cont=6", "rig.cont: unknown key"},
        BadOverride{"actors[0].motion.speed=-2", "actors[0].motion.speed: expected a number"},
        BadOverride{"room={size: [1, 2]}", "room.size: expected a list of 3 items, got 2"},
        BadOverride{"render.frames=0", "render.frames: expected an integer in [1, "}));

TEST(SceneOverrides, ErrorsOutsideTheOverriddenKeyStillPointIntoTheFile) {
  TempDir dir;
  const auto path = write_scene(dir.path(), "render:\n  fps: -1\n");
  const std::string msg = load_error(path, {"render.frames=5"});
  EXPECT_EQ(msg.rfind(path.string() + ":2: render.fps: ", 0), 0u) << msg;
}

}  // namespace
}  // namespace simcap
