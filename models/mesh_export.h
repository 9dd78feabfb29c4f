// Export of a body mesh, neutral or posed, to OBJ or PLY through Assimp's exporter, one
// sub-mesh per material region, so that it opens in Blender or MeshLab for inspection. (Rigged
// binary glTF, with skeleton and skin: models/body_gltf.h.)
#pragma once

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <span>

#include "models/body_mesh.h"

namespace simcap {

// Writes `mesh` to `path`, choosing the format from the extension: ".obj" (with a .mtl next to
// it) or ".ply" (ASCII, vertex colours). `positions` holds 3 floats per
// vertex (Skinner::skin output) or is empty for the neutral pose. `colors` are sRGB in [0, 1] per
// MaterialRegion. All files appear at once or not at all (written to a temporary folder next to
// `path`, then renamed). Throws Error naming the file for an unknown extension or a failed write.
void export_body_mesh(const std::filesystem::path& path, const BodyMesh& mesh,
                      std::span<const float> positions,
                      const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors);

}  // namespace simcap
