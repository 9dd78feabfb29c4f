#include "models/body_source.h"

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "models/x3d_humanoid.h"

namespace simcap {

BodySource body_file_source(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  BodySource source;
  source.file = file;
  source.format = extension == ".x3d" ? BodyFormat::x3d : BodyFormat::mesh;
  return source;
}

Body build_body(const BodySource& source) {
  switch (source.format) {
    case BodyFormat::x3d:
      return read_x3d_humanoid(source.file);
    case BodyFormat::mesh:
      return read_rigged_mesh(source.file, source.rigged);
    case BodyFormat::humanoid:
      break;
  }
  Skeleton skeleton = build_humanoid(source.parameters);
  BodyMesh mesh = build_body_mesh(skeleton, source.shape);
  return {std::move(skeleton), std::move(mesh), {}};
}

}  // namespace simcap
