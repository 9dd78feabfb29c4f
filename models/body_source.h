// Where an actor's body comes from: simcap's parametric humanoid (height, proportions, girth),
// an H-Anim X3D humanoid or a rigged mesh; one entry point builds its skeleton and skin.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "models/body.h"
#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "models/rigged_mesh.h"

namespace simcap {

enum class BodyFormat {
  humanoid,  // build_humanoid + build_body_mesh from `parameters` and `shape`
  x3d,       // read_x3d_humanoid(file)
  mesh,      // read_rigged_mesh(file, rigged)
};

struct BodySource {
  BodyFormat format = BodyFormat::humanoid;
  BodyParameters parameters;   // humanoid
  BodyShape shape;             // humanoid
  std::filesystem::path file;  // x3d, mesh
  RiggedMeshOptions rigged;    // mesh
};

// The source for a body file, its format chosen by the extension: .x3d an H-Anim humanoid,
// anything else a rigged mesh for Assimp (.glb, .gltf, .fbx, .dae, ...).
BodySource body_file_source(const std::filesystem::path& file);

// Builds the body. Files are read here; bad ones throw Error naming file:line.
Body build_body(const BodySource& source);

}  // namespace simcap
