#include "models/mesh_export.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <unistd.h>
#include <assimp/Exporter.hpp>

#include <algorithm>
#include <memory>
#include <string>

#include "core/error.h"

namespace simcap {
namespace {

struct Format {
  const char* extension;
  const char* assimp_id;
};
// ASCII PLY: Assimp 5.2's binary PLY exporter writes vertex colours as floats under a uchar
// header, which no reader can parse.
constexpr Format kFormats[] = {{".obj", "obj"}, {".ply", "ply"}};

// One aiMesh (with its material and node) per material region that has triangles.
std::unique_ptr<aiScene> make_scene(
    const BodyMesh& mesh, std::span<const float> positions,
    const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors) {
  auto scene = std::make_unique<aiScene>();
  scene->mRootNode = new aiNode("simcap_body");
  std::vector<int> regions;
  for (int r = 0; r < kMaterialRegionCount; ++r) {
    if (std::find(mesh.triangle_material.begin(), mesh.triangle_material.end(),
                  static_cast<MaterialRegion>(r)) != mesh.triangle_material.end()) {
      regions.push_back(r);
    }
  }
  const auto count = static_cast<unsigned>(regions.size());
  scene->mNumMeshes = scene->mNumMaterials = scene->mRootNode->mNumChildren = count;
  scene->mMeshes = new aiMesh*[count];
  scene->mMaterials = new aiMaterial*[count];
  scene->mRootNode->mChildren = new aiNode*[count];

  for (unsigned k = 0; k < count; ++k) {
    const auto region = static_cast<MaterialRegion>(regions[k]);
    const aiString name(std::string(material_region_name(region)));
    const Eigen::Vector3f& c = colors[regions[k]];

    auto* material = new aiMaterial();
    material->AddProperty(&name, AI_MATKEY_NAME);
    const aiColor3D diffuse(c.x(), c.y(), c.z());
    material->AddProperty(&diffuse, 1, AI_MATKEY_COLOR_DIFFUSE);
    scene->mMaterials[k] = material;

    std::vector<unsigned> local(mesh.vertices.size(), ~0u);
    std::vector<unsigned> used;
    std::vector<std::array<unsigned, 3>> faces;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
      if (mesh.triangle_material[t] != region) continue;
      std::array<unsigned, 3> f;
      for (int i = 0; i < 3; ++i) {
        const std::uint32_t v = mesh.triangles[t][i];
        if (local[v] == ~0u) {
          local[v] = static_cast<unsigned>(used.size());
          used.push_back(v);
        }
        f[i] = local[v];
      }
      faces.push_back(f);
    }
    auto* m = new aiMesh();
    m->mName = name;
    m->mMaterialIndex = k;
    m->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    m->mNumVertices = static_cast<unsigned>(used.size());
    m->mVertices = new aiVector3D[used.size()];
    m->mColors[0] = new aiColor4D[used.size()];
    for (size_t i = 0; i < used.size(); ++i) {
      const size_t v = used[i];
      m->mVertices[i] =
          positions.empty()
              ? aiVector3D(mesh.vertices[v].x(), mesh.vertices[v].y(), mesh.vertices[v].z())
              : aiVector3D(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
      m->mColors[0][i] = aiColor4D(c.x(), c.y(), c.z(), 1.0f);
    }
    m->mNumFaces = static_cast<unsigned>(faces.size());
    m->mFaces = new aiFace[faces.size()];
    for (size_t i = 0; i < faces.size(); ++i) {
      m->mFaces[i].mNumIndices = 3;
      m->mFaces[i].mIndices = new unsigned[3]{faces[i][0], faces[i][1], faces[i][2]};
    }
    scene->mMeshes[k] = m;

    auto* node = new aiNode(name.C_Str());
    node->mParent = scene->mRootNode;
    node->mNumMeshes = 1;
    node->mMeshes = new unsigned[1]{k};
    scene->mRootNode->mChildren[k] = node;
  }
  return scene;
}

// A folder next to the target that disappears with this object, whatever happened.
class TempFolder {
 public:
  explicit TempFolder(const std::filesystem::path& target)
      : path_(target.parent_path() /
              ("." + target.filename().string() + ".tmp" + std::to_string(getpid()))) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

void export_body_mesh(const std::filesystem::path& path, const BodyMesh& mesh,
                      std::span<const float> positions,
                      const std::array<Eigen::Vector3f, kMaterialRegionCount>& colors) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char ch) { return std::tolower(ch); });
  const Format* format = nullptr;
  for (const Format& f : kFormats) {
    if (extension == f.extension) format = &f;
  }
  if (!format) {
    throw_input_error(path, 0, "",
                      "unknown mesh format '" + extension + "' (expected .obj or .ply)");
  }
  if (!positions.empty() && positions.size() < 3 * mesh.vertices.size()) {
    throw Error("mesh export: " + std::to_string(positions.size()) + " posed coordinates for " +
                std::to_string(mesh.vertices.size()) + " vertices");
  }
  const std::filesystem::path target = std::filesystem::absolute(path);
  std::filesystem::create_directories(target.parent_path());
  const TempFolder temp(target);
  const std::unique_ptr<aiScene> scene = make_scene(mesh, positions, colors);
  Assimp::Exporter exporter;
  const std::filesystem::path staged = temp.path() / target.filename();
  if (exporter.Export(scene.get(), format->assimp_id, staged.string(),
                      aiProcess_GenSmoothNormals) != aiReturn_SUCCESS) {
    throw_input_error(path, 0, "",
                      std::string("Assimp could not write it: ") + exporter.GetErrorString());
  }
  // Companion files (the OBJ's .mtl) first, so the main file never names a missing one.
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(temp.path())) {
    if (entry.path().filename() != target.filename()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  files.push_back(staged);
  for (const auto& file : files) {
    std::error_code ec;
    std::filesystem::rename(file, target.parent_path() / file.filename(), ec);
    if (ec)
      throw_input_error(path, 0, "", "cannot move the written file into place: " + ec.message());
  }
}

}  // namespace simcap
