// A body as the renderer and the ground truth use it: a skeleton and its skinned mesh, with the
// notes of an import (what it changed or could not use).
#pragma once

#include <string>
#include <vector>

#include "models/body_mesh.h"
#include "models/skeleton.h"

namespace simcap {

struct Body {
  Skeleton skeleton;
  BodyMesh mesh;
  // What an import changed or could not use, one line each (`simcap model info` prints them).
  std::vector<std::string> notes;
};

}  // namespace simcap
