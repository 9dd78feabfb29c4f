// A simcap body in a glTF file: the skeleton as a node tree (H-Anim names, or another naming),
// the skinned mesh with one primitive per material region and its skin, posed by the nodes;
// and a motion as an animation of those nodes.
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "models/body_mesh.h"
#include "models/gltf_builder.h"
#include "models/pose.h"
#include "models/skeleton.h"

namespace simcap {

struct GltfBody {
  int mesh_node = -1;
  std::vector<int> joint_nodes;  // per skeleton joint (sites included)
};

// Maps an H-Anim joint name to the name its node gets (empty function: the H-Anim name).
using JointNamer = std::function<std::string(const std::string& hanim)>;

// Adds the body named `name` posed by `pose`: joint node j has translation = the skeleton offset
// (the root: pose.root_position) and rotation = pose.rotations[j], so the readers' forward
// kinematics is simcap's; the vertices are the neutral (bind) pose with four weights each, and
// inverse bind matrices translate each joint's neutral centre to the origin. `colors` are sRGB
// per material region.
GltfBody add_gltf_body(GltfBuilder& builder, const std::string& name, const Skeleton& skeleton,
                       const BodyMesh& mesh,
                       const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors,
                       const Pose& pose, const JointNamer& namer = {});

// The animation channels that move `body` through `frames` (poses of `skeleton`) at `fps`: the
// root's translation and every joint's rotation, one key per frame (linear interpolation).
// Several bodies' channels make one animation (GltfBuilder::add_animation).
std::vector<GltfBuilder::Channel> gltf_motion_channels(const GltfBody& body,
                                                       const Skeleton& skeleton,
                                                       const std::vector<Pose>& frames, double fps);

// Area-weighted vertex normals of a triangle mesh (unit length; zero for unused vertices).
std::vector<Eigen::Vector3f> vertex_normals(
    const std::vector<Eigen::Vector3f>& vertices,
    const std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace simcap
