// Where an actor's body comes from: simcap's parametric humanoid (height, proportions, girth),
// an H-Anim X3D humanoid or a rigged mesh; one entry point builds its skeleton and skin.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "models/body_mesh.h"
#include "models/humanoid.h"
#include "models/skeleton.h"

namespace simcap {

enum class BodyFormat {
  humanoid,  // build_humanoid + build_body_mesh from `parameters` and `shape`
  x3d,       // read_x3d_humanoid(file)
};

struct BodySource {
  BodyFormat format = BodyFormat::humanoid;
  BodyParameters parameters;   // humanoid
  BodyShape shape;             // humanoid
  std::filesystem::path file;  // x3d
};

struct Body {
  Skeleton skeleton;
  BodyMesh mesh;
  // What an import changed or could not use, one line each (`simcap model info` prints them).
  std::vector<std::string> notes;
};

// The source for a body file, its format chosen by the extension (.x3d); throws Error naming
// the file for another extension.
BodySource body_file_source(const std::filesystem::path& file);

// Builds the body. Files are read here; bad ones throw Error naming file:line.
Body build_body(const BodySource& source);

}  // namespace simcap
