// Reader of rigged meshes through Assimp (glTF 2.0 / GLB, FBX, Collada and the other formats
// Assimp reads with bones): skeleton, skin weights and bind pose from the file, the bones'
// names mapped to H-Anim joints by a table (models/joint_names.h).
#pragma once

#include <filesystem>

#include "models/body.h"
#include "models/joint_names.h"

namespace simcap {

struct RiggedMeshOptions {
  JointNaming naming = JointNaming::automatic;
  // Metres per file unit; 0 picks among metres, centimetres, millimetres and inches the unit
  // that makes the skin closest to 1.7 m tall.
  double metres_per_unit = 0.0;
};

// Reads every mesh of the file that has bones, in its bind pose (each bone's bind transform is
// the inverse of its offset matrix; nodes without a bone follow their parent's). Mapped bones
// become joints at their bind positions, their parents the nearest mapped ancestors; a bone the
// table does not name gives its weights to its nearest mapped ancestor. Bones mapped to
// skull_tip, l/r_hand_tip or l/r_toe_tip become end sites. The body is then scaled to metres,
// turned about +Y so that its left hip lies towards +X (facing +Z), and lifted so that its
// lowest skin point is on the floor; finish_imported_body() completes it. Throws Error naming
// the file: Assimp's message for a file it cannot read, no bones, no humanoid_root, two bones
// mapped to one joint, a head not above the hips (+Y is up), and what finish_imported_body()
// refuses.
Body read_rigged_mesh(const std::filesystem::path& path, const RiggedMeshOptions& options = {});

}  // namespace simcap
