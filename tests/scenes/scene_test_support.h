// Helpers shared by the scene tests: scene files in a temporary folder, the message of a failed
// load, and a field-by-field comparison of two scenes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "core/atomic_file.h"
#include "core/error.h"
#include "scenes/scene.h"
#include "tests/support/error_of.h"

namespace simcap::testing {

inline std::filesystem::path write_scene(const std::filesystem::path& dir, const std::string& text,
                                         const std::string& name = "scene.yaml") {
  const auto path = dir / name;
  write_text_atomic(path, text);
  return path;
}

// The Error message of load_scene, or "<no error>".
inline std::string load_error(const std::filesystem::path& path,
                              const std::vector<std::string>& overrides = {}) {
  return error_of([&] { load_scene(path, overrides); });
}

inline void expect_cameras_equal(const Camera& a, const Camera& b, double tol) {
  SCOPED_TRACE("camera " + a.name);
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_LE((a.K - b.K).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.dist - b.dist).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.R - b.R).cwiseAbs().maxCoeff(), tol);
  EXPECT_LE((a.t - b.t).cwiseAbs().maxCoeff(), tol);
}

// Every field except `source` (the file each was loaded from).
inline void expect_scenes_equal(const Scene& a, const Scene& b, double tol = 1e-12) {
  const auto near3 = [tol](const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
    return (x - y).cwiseAbs().maxCoeff() <= tol;
  };
  EXPECT_TRUE(near3(a.room.size, b.room.size));
  EXPECT_EQ(a.room.floor_color, b.room.floor_color);
  EXPECT_EQ(a.room.wall_color, b.room.wall_color);
  EXPECT_EQ(a.room.floor_texture, b.room.floor_texture);
  EXPECT_EQ(a.room.wall_texture, b.room.wall_texture);

  ASSERT_EQ(a.occluders.size(), b.occluders.size());
  for (std::size_t i = 0; i < a.occluders.size(); ++i) {
    const Occluder &x = a.occluders[i], &y = b.occluders[i];
    SCOPED_TRACE("occluder " + x.name);
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.name, y.name);
    EXPECT_TRUE(near3(x.position, y.position));
    EXPECT_TRUE(near3(x.size, y.size));
    EXPECT_NEAR(x.yaw_rad, y.yaw_rad, tol);
    EXPECT_EQ(x.mesh, y.mesh);
    EXPECT_NEAR(x.mesh_scale, y.mesh_scale, tol);
    EXPECT_EQ(x.color, y.color);
  }

  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    const Light &x = a.lights[i], &y = b.lights[i];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_TRUE(near3(x.direction, y.direction));
    EXPECT_TRUE(near3(x.position, y.position));
    EXPECT_NEAR(x.intensity, y.intensity, tol);
    EXPECT_EQ(x.shadows, y.shadows);
  }
  EXPECT_NEAR(a.ambient, b.ambient, tol);

  ASSERT_EQ(a.cameras.size(), b.cameras.size());
  for (std::size_t i = 0; i < a.cameras.size(); ++i) {
    expect_cameras_equal(a.cameras[i], b.cameras[i], tol);
  }

  ASSERT_EQ(a.actors.size(), b.actors.size());
  for (std::size_t i = 0; i < a.actors.size(); ++i) {
    const Actor &x = a.actors[i], &y = b.actors[i];
    SCOPED_TRACE("actor " + x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_NEAR(x.body.parameters.height, y.body.parameters.height, tol);
    const BodyProportions &p = x.body.parameters.proportions, &q = y.body.parameters.proportions;
    for (const auto& [u, v] : {std::pair{p.shoulder_height, q.shoulder_height},
                               {p.chin_height, q.chin_height},
                               {p.hip_height, q.hip_height},
                               {p.knee_height, q.knee_height},
                               {p.ankle_height, q.ankle_height},
                               {p.upper_arm, q.upper_arm},
                               {p.forearm, q.forearm},
                               {p.hand, q.hand},
                               {p.foot_length, q.foot_length},
                               {p.shoulder_width, q.shoulder_width},
                               {p.hip_width, q.hip_width},
                               {p.shoulder_joint_spacing, q.shoulder_joint_spacing},
                               {p.hip_joint_spacing, q.hip_joint_spacing},
                               {p.shoulder_rise, q.shoulder_rise}}) {
      EXPECT_NEAR(u, v, tol);
    }
    EXPECT_NEAR(x.body.shape.girth, y.body.shape.girth, tol);
    EXPECT_EQ(x.body.format, y.body.format);
    EXPECT_EQ(x.body.file, y.body.file);
    EXPECT_EQ(x.body.rigged.naming, y.body.rigged.naming);
    EXPECT_EQ(x.body.rigged.metres_per_unit, y.body.rigged.metres_per_unit);
    EXPECT_EQ(x.limits, y.limits);
    EXPECT_EQ(x.colors, y.colors);
    EXPECT_EQ(x.motion.bvh, y.motion.bvh);
    EXPECT_EQ(x.motion.amc, y.motion.amc);
    EXPECT_EQ(x.motion.asf, y.motion.asf);
    EXPECT_EQ(x.motion.amc_fps, y.motion.amc_fps);
    EXPECT_NEAR(x.motion.bvh_metres_per_unit, y.motion.bvh_metres_per_unit, tol);
    EXPECT_EQ(x.motion.procedural.kind, y.motion.procedural.kind);
    EXPECT_NEAR(x.motion.procedural.duration_s, y.motion.procedural.duration_s, tol);
    EXPECT_NEAR(x.motion.procedural.speed_m_s, y.motion.procedural.speed_m_s, tol);
    EXPECT_NEAR(x.motion.procedural.path_radius, y.motion.procedural.path_radius, tol);
    EXPECT_NEAR(x.motion.procedural.turn_degrees, y.motion.procedural.turn_degrees, tol);
    const ProceduralSpec &m = x.motion.procedural, &n = y.motion.procedural;
    EXPECT_EQ(m.jumps.count, n.jumps.count);
    EXPECT_NEAR(m.jumps.distance_m, n.jumps.distance_m, tol);
    EXPECT_NEAR(m.jumps.height_m, n.jumps.height_m, tol);
    EXPECT_NEAR(m.turnaround.distance_m, n.turnaround.distance_m, tol);
    EXPECT_EQ(m.squat.count, n.squat.count);
    EXPECT_NEAR(m.squat.depth, n.squat.depth, tol);
    EXPECT_EQ(m.arms_cross.count, n.arms_cross.count);
    EXPECT_EQ(m.side_steps.count, n.side_steps.count);
    EXPECT_NEAR(m.side_steps.distance_m, n.side_steps.distance_m, tol);
    EXPECT_EQ(m.bend_forward.count, n.bend_forward.count);
    EXPECT_EQ(m.kick.count, n.kick.count);
    EXPECT_NEAR(m.kick.height, n.kick.height, tol);
    EXPECT_NEAR(m.arm_swings.frequency_hz, n.arm_swings.frequency_hz, tol);
    EXPECT_NEAR(m.arm_swings.amplitude_deg, n.arm_swings.amplitude_deg, tol);
    EXPECT_TRUE(near3(x.offset, y.offset));
    EXPECT_NEAR(x.yaw_rad, y.yaw_rad, tol);
    EXPECT_NEAR(x.time_offset_s, y.time_offset_s, tol);
  }

  EXPECT_NEAR(a.render.fps, b.render.fps, tol);
  EXPECT_EQ(a.render.first_frame, b.render.first_frame);
  EXPECT_EQ(a.render.frame_count, b.render.frame_count);
  EXPECT_EQ(a.render.samples_per_pixel, b.render.samples_per_pixel);
  EXPECT_EQ(a.render.seed, b.render.seed);
  EXPECT_EQ(a.render.normals, b.render.normals);
  EXPECT_NEAR(a.noise.rgb_sigma, b.noise.rgb_sigma, tol);
  EXPECT_NEAR(a.noise.depth_sigma_m, b.noise.depth_sigma_m, tol);
}

}  // namespace simcap::testing
