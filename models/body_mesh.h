// The skinned body: a closed triangle mesh of a clothed adult around a humanoid skeleton, with
// linear-blend-skinning weights, an H-Anim segment per vertex and a material region per triangle.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "models/skeleton.h"

namespace simcap {

// Material regions whose colours a scene sets.
enum class MaterialRegion : std::uint8_t { skin = 0, shirt, trousers, shoes, hair };
inline constexpr int kMaterialRegionCount = 5;
std::string_view material_region_name(MaterialRegion region);

struct BodyMesh {
  std::vector<Eigen::Vector3f> vertices;                // neutral pose, world frame, metres
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  // Up to four skinning influences per vertex: skeleton joint indices and weights summing to 1
  // (unused slots have weight 0).
  std::vector<std::array<std::uint16_t, 4>> influence_joint;
  std::vector<std::array<float, 4>> influence_weight;
  // The skeleton joint whose H-Anim segment the vertex belongs to (its part label).
  std::vector<std::uint16_t> vertex_segment;
  std::vector<MaterialRegion> triangle_material;
};

struct BodyShape {
  double girth = 1.0;  // scales every limb and torso radius (1 = average adult)
};

// Builds the body around `skeleton` (from build_humanoid) in its neutral pose.
BodyMesh build_body_mesh(const Skeleton& skeleton, const BodyShape& shape = {});

// Linear-blend skinning of a BodyMesh. Built once per body; skin() is called every frame.
// It keeps a pointer to the mesh, which must outlive it.
class Skinner {
 public:
  Skinner(const Skeleton& skeleton, const BodyMesh& mesh);
  // Writes the posed vertices as packed float triples (x, y, z per vertex) into `out`, which
  // must hold 3 * vertex_count + 1 floats (Embree reads 16 bytes at the last vertex).
  // `joint_world` is forward_kinematics() of the pose. Parallel over vertices (TBB).
  void skin(const std::vector<Eigen::Isometry3d>& joint_world, float* out) const;
  int vertex_count() const;

 private:
  const BodyMesh* mesh_;
  std::vector<Eigen::Isometry3d> inverse_bind_;  // inverse neutral world transform per joint
};

}  // namespace simcap
