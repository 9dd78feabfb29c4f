// The scenes shipped in scenes/: each loads and round-trips; studio4 is the documented default;
// every camera sees where the actor starts; the occluders of occluders.yaml hide limbs from some
// cameras part of the time without ever intersecting the body.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "models/body_source.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "models/pose.h"
#include "scenes/scene.h"
#include "tests/scenes/scene_test_support.h"
#include "tests/support/temp_dir.h"

namespace simcap {
namespace {

using simcap::testing::TempDir;

const std::vector<std::string> kShipped = {
    "studio4",     "studio8",  "occluders",          "monocular",
    "x3d_joe",     "gestures", "monocular_gestures", "two_people",
    "three_people"};

// The actor's joint positions in the room for every frame at the scene's frame rate.
std::vector<std::vector<Eigen::Vector3d>> world_joints(const Scene& scene, const Actor& actor,
                                                       const Skeleton& skeleton) {
  const Motion motion = load_motion(actor.motion, skeleton, scene.render.fps);
  const Eigen::Isometry3d placement = actor_placement(actor);
  std::vector<std::vector<Eigen::Vector3d>> out;
  for (const Pose& pose : motion.frames) {
    auto joints = joint_positions(skeleton, pose);
    for (auto& p : joints) p = placement * p;
    out.push_back(std::move(joints));
  }
  return out;
}

// Signed distance-like measure from a point to an occluder's solid (<= 0 inside).
double distance_to(const Occluder& o, const Eigen::Vector3d& p) {
  const Eigen::Vector3d q =
      Eigen::AngleAxisd(-o.yaw_rad, Eigen::Vector3d::UnitY()) * (p - o.position);
  const double below = -q.y(), above = q.y() - o.size.y();
  const double vertical = std::max(below, above);
  double horizontal = 0;
  if (o.kind == Occluder::Kind::cylinder) {
    horizontal = std::hypot(q.x(), q.z()) - 0.5 * o.size.x();
  } else {
    horizontal = std::max(std::abs(q.x()) - 0.5 * o.size.x(), std::abs(q.z()) - 0.5 * o.size.z());
  }
  if (horizontal > 0 && vertical > 0) return std::hypot(horizontal, vertical);
  return std::max(horizontal, vertical);
}

// True when the straight segment from `a` to `b` passes through the occluder (1 cm steps).
bool blocks(const Occluder& o, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const int steps = static_cast<int>(std::ceil((b - a).norm() / 0.01));
  for (int i = 1; i < steps; ++i) {
    if (distance_to(o, a + (b - a) * (static_cast<double>(i) / steps)) <= 0) return true;
  }
  return false;
}

TEST(ShippedScenes, AllLoadAndRoundTrip) {
  for (const std::string& name : kShipped) {
    SCOPED_TRACE(name);
    const Scene s = load_scene(shipped_scene_path(name));
    EXPECT_FALSE(s.cameras.empty());
    ASSERT_EQ(s.actors.size(), name == "two_people" ? 2u : name == "three_people" ? 3u : 1u);
    TempDir dir;
    const Scene back = load_scene(testing::write_scene(dir.path(), scene_to_yaml(s)));
    testing::expect_scenes_equal(s, back);
  }
}

TEST(ShippedScenes, NothingElseIsShippedUntested) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::directory_iterator(SIMCAP_SOURCE_DIR "/scenes")) {
    if (e.path().extension() == ".yaml") found.push_back(e.path().stem().string());
  }
  std::sort(found.begin(), found.end());
  auto expected = kShipped;
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(found, expected);
}

// Each `--set key=a|b` that the table of shipped scenes in scenes/README.md suggests for a scene
// loads with that scene, every alternative.
TEST(ShippedScenes, TheOverridesTheReadmeSuggestsLoad) {
  // Parsed by hand: GCC 12's -Wmaybe-uninitialized misfires inside <regex> in the sanitizer build.
  std::ifstream readme(SIMCAP_SOURCE_DIR "/scenes/README.md");
  const std::string row = "| `", named = ".yaml` |", set = "`--set ";
  int suggested = 0;
  for (std::string line; std::getline(readme, line);) {
    const size_t name_end = line.find(named);
    if (!line.starts_with(row) || name_end == std::string::npos) continue;
    const std::string scene = line.substr(row.size(), name_end - row.size());
    for (size_t at = line.find(set); at != std::string::npos; at = line.find(set, at + 1)) {
      const size_t end = line.find('`', at + set.size());
      ASSERT_NE(end, std::string::npos) << line;
      const std::string text = line.substr(at + set.size(), end - at - set.size());
      const size_t eq = text.find('=');
      ASSERT_NE(eq, std::string::npos) << line;
      // The table escapes the bar between alternatives: "a\|b".
      std::string values = text.substr(eq + 1);
      std::erase(values, '\\');
      std::stringstream alternatives(values);
      for (std::string value; std::getline(alternatives, value, '|');) {
        const std::string override = text.substr(0, eq) + "=" + value;
        SCOPED_TRACE(scene + ": " + override);
        EXPECT_NO_THROW(load_scene(shipped_scene_path(scene), {override}));
        ++suggested;
      }
    }
  }
  EXPECT_GE(suggested, 3);
}

TEST(ShippedScenes, Studio4IsTheDocumentedDefault) {
  const Scene s = load_scene(shipped_scene_path("studio4"));
  EXPECT_EQ(s.room.size, Eigen::Vector3d(5, 3, 5));
  ASSERT_EQ(s.cameras.size(), 4u);
  for (const Camera& cam : s.cameras) {
    SCOPED_TRACE(cam.name);
    EXPECT_EQ(cam.width, 640);
    EXPECT_EQ(cam.height, 480);
    const Eigen::Vector3d c = cam.centre();
    EXPECT_NEAR(c.y(), 2.5, 1e-12);
    EXPECT_GT(std::abs(c.x()), 2.0);  // in a corner of the 5 m x 5 m room
    EXPECT_GT(std::abs(c.z()), 2.0);
    // The optical axis passes through the room centre at 1 m height.
    const Eigen::Vector3d at = cam.to_camera({0, 1, 0});
    EXPECT_NEAR(at.x(), 0, 1e-9);
    EXPECT_NEAR(at.y(), 0, 1e-9);
  }
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_TRUE(s.lights[0].shadows);
  EXPECT_GT(s.ambient, 0);
  EXPECT_EQ(s.render.fps, 30.0);
  EXPECT_EQ(s.actors[0].motion.bvh.filename(), "cmu_131_01_start_walk_stop.bvh");
}

TEST(ShippedScenes, EveryCameraSeesWhereTheActorStarts) {
  for (const std::string& name : kShipped) {
    SCOPED_TRACE(name);
    const Scene s = load_scene(shipped_scene_path(name));
    const Actor& actor = s.actors[0];
    const Skeleton skeleton = build_body(actor.body).skeleton;
    const Motion motion = load_motion(actor.motion, skeleton, s.render.fps);
    ASSERT_FALSE(motion.frames.empty());
    Eigen::Vector3d start = actor_placement(actor) * motion.frames[0].root_position;
    start.y() = 1.0;
    for (const Camera& cam : s.cameras) {
      EXPECT_TRUE(cam.in_frustum(start, 20.0)) << cam.name << " does not see " << start.transpose();
    }
  }
}

TEST(ShippedScenes, OccludersHideLimbsPartOfTheTimeAndNeverTouchTheBody) {
  const Scene s = load_scene(shipped_scene_path("occluders"));
  const Scene studio = load_scene(shipped_scene_path("studio4"));
  ASSERT_EQ(s.occluders.size(), 3u);
  ASSERT_EQ(s.cameras.size(), studio.cameras.size());
  for (std::size_t i = 0; i < s.cameras.size(); ++i) {
    testing::expect_cameras_equal(s.cameras[i], studio.cameras[i], 0);
  }
  const Actor& actor = s.actors[0];
  const Skeleton skeleton = build_body(actor.body).skeleton;
  const auto frames = world_joints(s, actor, skeleton);
  std::vector<int> limbs;
  for (const char* j : {"l_knee", "r_knee", "l_talocrural", "r_talocrural", "l_elbow", "r_elbow",
                        "l_radiocarpal", "r_radiocarpal"}) {
    limbs.push_back(skeleton.find(j));
    ASSERT_GE(limbs.back(), 0) << j;
  }

  std::vector<int> hidden_by(s.occluders.size(), 0);  // (frame, camera, limb) rays each blocks
  std::vector<int> hidden_in_camera(s.cameras.size(), 0);
  int frames_with_hidden_limb = 0;
  double clearance = INFINITY;
  for (const auto& joints : frames) {
    for (const auto& p : joints) {
      for (const Occluder& o : s.occluders) clearance = std::min(clearance, distance_to(o, p));
    }
    bool any = false;
    for (std::size_t c = 0; c < s.cameras.size(); ++c) {
      for (int j : limbs) {
        bool hidden = false;
        for (std::size_t o = 0; o < s.occluders.size(); ++o) {
          if (blocks(s.occluders[o], s.cameras[c].centre(), joints[j])) {
            ++hidden_by[o];
            hidden = true;
          }
        }
        hidden_in_camera[c] += hidden;
        any = any || hidden;
      }
    }
    frames_with_hidden_limb += any;
  }
  // Joint centres lie inside the body; 0.15 m leaves room for the flesh around them.
  EXPECT_GT(clearance, 0.15);
  for (std::size_t o = 0; o < s.occluders.size(); ++o) {
    EXPECT_GT(hidden_by[o], 0) << s.occluders[o].name << " hides nothing";
  }
  const double n = static_cast<double>(frames.size());
  EXPECT_GT(frames_with_hidden_limb / n, 0.3);
  for (std::size_t c = 0; c < s.cameras.size(); ++c) {
    // Part of the time: no camera loses most of its limb views.
    EXPECT_LT(hidden_in_camera[c] / (n * limbs.size()), 0.5) << s.cameras[c].name;
  }
}

}  // namespace
}  // namespace simcap
