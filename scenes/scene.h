// A scene: the room, static occluders, lights, the camera rig, the actors and their motions, and
// the render settings. Loaded from a human-written YAML file with every default filled in.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/camera.h"
#include "models/body_mesh.h"
#include "models/body_source.h"
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "scenes/capture_settings.h"

namespace simcap {

// Colours are sRGB values in [0, 1] as written in the file; the renderer linearizes them.
using Rgb = Eigen::Vector3f;

struct Room {
  Eigen::Vector3d size{4.0, 3.0, 4.0};  // x (width), y (height), z (depth); centred on x = z = 0
  Rgb floor_color{0.55f, 0.55f, 0.52f};
  Rgb wall_color{0.80f, 0.80f, 0.78f};
  std::filesystem::path floor_texture;  // optional image, tiled once per metre
  std::filesystem::path wall_texture;   // optional image, tiled once per metre
};

struct Occluder {
  enum class Kind { box, cylinder, mesh };
  Kind kind = Kind::box;
  std::string name;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // centre of the base, on the floor
  Eigen::Vector3d size{1.0, 1.0, 1.0};  // box: x, y, z extents; cylinder: diameter, height, -
  double yaw_rad = 0.0;                 // rotation about +Y
  std::filesystem::path mesh;           // kind == mesh: any file Assimp reads
  double mesh_scale = 1.0;
  Rgb color{0.5f, 0.35f, 0.2f};
};

struct Light {
  enum class Kind { directional, point };
  Kind kind = Kind::directional;
  Eigen::Vector3d direction{-0.3, -1.0, -0.4};  // directional: direction the light travels
  Eigen::Vector3d position{0.0, 2.8, 0.0};      // point
  double intensity = 0.8;
  bool shadows = true;
  std::vector<LightKeyframe> keyframes;  // in time order; empty: the light never changes
};

// A subject drawn from the render seed (resolve_seeded_choices): the height moves uniformly by up
// to +-height metres; each segment length and breadth (upper arm, forearm, hand, foot, shoulder
// and hip widths) and the leg's share of the height by up to +-proportions of itself.
struct BodyVariation {
  double height = 0.0;
  double proportions = 0.0;
};

struct Actor {
  std::string name = "actor0";
  BodySource body;     // simcap's humanoid (parameters, shape) or a body file
  BodyVariation vary;  // per-seed variation of the humanoid (scenes/seeded_choices.cpp)
  std::array<Rgb, kMaterialRegionCount> colors = {
      Rgb{0.85f, 0.66f, 0.53f}, Rgb{0.20f, 0.35f, 0.65f}, Rgb{0.25f, 0.25f, 0.30f},
      Rgb{0.10f, 0.10f, 0.10f}, Rgb{0.25f, 0.17f, 0.10f}};  // skin, shirt, trousers, shoes, hair
  MotionSource motion;
  // Joint limits for this actor's trackers (a URDF as models/assets/humanoid_limits.urdf);
  // empty: the shipped ones.
  std::filesystem::path limits;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // added to the motion's root path
  double yaw_rad = 0.0;                              // rotation of the whole motion about +Y
  double time_offset_s = 0.0;                        // the actor's clock starts this much later
};

struct RenderSettings {
  double fps = 30.0;
  int first_frame = 0;
  int frame_count = -1;  // -1: as long as the longest actor's motion
  int samples_per_pixel = 1;
  std::uint64_t seed = 1;
  bool normals = false;  // also write camNN/normal/%06d.exr
  double shutter = 0;    // exposure time as a fraction of the frame period (motion blur)
};

struct SensorNoise {
  double rgb_sigma = 0.0;      // Gaussian noise on 8-bit RGB levels
  double depth_sigma_m = 0.0;  // Gaussian noise on depth, metres
};

struct Scene {
  std::filesystem::path source;  // the file it was loaded from (relative paths resolve here)
  Room room;
  std::vector<Occluder> occluders;
  std::vector<Light> lights;
  double ambient = 0.3;
  std::vector<Camera> cameras;  // the rig, resolved to explicit cameras
  CalibrationError calibration_error;
  CaptureTiming timing;
  std::vector<Actor> actors;
  RenderSettings render;
  SensorNoise noise;
};

// Loads and validates a scene file. `overrides` are "key.path=value" strings applied to the YAML
// before validation (e.g. "rig.count=6", "render.frames=30"), used by --set and stress sweeps.
// Unknown keys, wrong types and out-of-range values throw Error naming the key path and line.
Scene load_scene(const std::filesystem::path& path, const std::vector<std::string>& overrides = {});

// The scene as YAML with every default filled in (the dataset's scene.yaml); load_scene() of it
// gives the same scene back.
std::string scene_to_yaml(const Scene& scene);

// Fixes what the scene leaves to the render seed: each actor's body within its `vary` ranges
// (drawn from render.seed and the actor's index; `vary` is then cleared) and a gesture corpus'
// seed 0 (it becomes render.seed). The renderer calls it after --seed, so that the dataset's
// scene.yaml states the subject and corpus it shows.
void resolve_seeded_choices(Scene& scene);
// Where an actor's motion is put in the room: every pose (root path and joints, in the motion's
// own frame) is rotated by yaw_rad about the world +Y axis through the origin, then moved by
// offset: world = placement * motion point.
Eigen::Isometry3d actor_placement(const Actor& actor);

// The light as it is at scene time `time_s`, its keyframes applied.
Light light_at(const Light& light, double time_s);

// A scene shipped in simcap's scenes/ folder, by name: "studio4" (the default), "studio8",
// "occluders", "monocular". Throws Error listing the shipped scenes when there is no such one.
std::filesystem::path shipped_scene_path(std::string_view name);

}  // namespace simcap
