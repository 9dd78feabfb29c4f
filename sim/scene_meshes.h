// The static geometry of a scene as triangle meshes: the room's floor, walls and ceiling, and
// the occluders (boxes, cylinders, or any mesh file Assimp reads), placed in world coordinates.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "scenes/scene.h"

namespace simcap {

struct TriangleMesh {
  std::vector<Eigen::Vector3f> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // Per-vertex shading normals; empty means flat shading with each triangle's own normal.
  std::vector<Eigen::Vector3f> normals;
};

// One flat surface of the room. Texture coordinates are metres along `tex_u` and `tex_v`
// (world directions), so a texture image repeats once per metre.
struct RoomSurface {
  TriangleMesh mesh;
  bool floor = false;  // floor colour/texture; otherwise wall colour/texture (walls, ceiling)
  Eigen::Vector3f tex_u = Eigen::Vector3f::UnitX();
  Eigen::Vector3f tex_v = Eigen::Vector3f::UnitZ();
};

// Floor (y = 0), ceiling (y = size.y) and four walls of the room centred on x = z = 0.
std::vector<RoomSurface> room_surfaces(const Room& room);

// An occluder in world coordinates: a box or a 48-sided cylinder standing on its base at
// `position`, or a mesh file (relative paths resolve against `base_dir`) scaled by mesh_scale
// whose bounding-box base centre is placed at `position`; all turned by yaw about +Y.
// Throws Error naming the occluder and file when a mesh cannot be read.
TriangleMesh occluder_mesh(const Occluder& occluder, const std::filesystem::path& base_dir);

}  // namespace simcap
