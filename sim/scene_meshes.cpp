#include "sim/scene_meshes.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <assimp/Importer.hpp>
#include <cmath>

#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;
namespace {

// A quad a-b-c-d (counter-clockwise seen from the side `normal` points to) as two triangles.
void add_quad(TriangleMesh& mesh, const Eigen::Vector3f& a, const Eigen::Vector3f& b,
              const Eigen::Vector3f& c, const Eigen::Vector3f& d) {
  const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
  mesh.vertices.insert(mesh.vertices.end(), {a, b, c, d});
  mesh.triangles.push_back({base, base + 1, base + 2});
  mesh.triangles.push_back({base, base + 2, base + 3});
}

TriangleMesh box_mesh(const Eigen::Vector3f& size) {
  const float x = 0.5f * size.x(), y = size.y(), z = 0.5f * size.z();
  const Eigen::Vector3f p[8] = {{-x, 0, -z}, {x, 0, -z}, {x, y, -z}, {-x, y, -z},
                                {-x, 0, z},  {x, 0, z},  {x, y, z},  {-x, y, z}};
  TriangleMesh m;
  add_quad(m, p[4], p[5], p[6], p[7]);  // +z
  add_quad(m, p[1], p[0], p[3], p[2]);  // -z
  add_quad(m, p[5], p[1], p[2], p[6]);  // +x
  add_quad(m, p[0], p[4], p[7], p[3]);  // -x
  add_quad(m, p[7], p[6], p[2], p[3]);  // +y
  add_quad(m, p[0], p[1], p[5], p[4]);  // -y
  return m;
}

// Side vertices carry radial normals (smooth shading); the caps have their own flat vertices.
TriangleMesh cylinder_mesh(float radius, float height) {
  constexpr int kSides = 48;
  TriangleMesh m;
  auto ring = [&](float y, bool radial_normals, const Eigen::Vector3f& cap_normal) {
    const auto first = static_cast<std::uint32_t>(m.vertices.size());
    for (int i = 0; i < kSides; ++i) {
      const float a = 2.0f * static_cast<float>(M_PI) * i / kSides;
      const Eigen::Vector3f n(std::sin(a), 0, std::cos(a));
      m.vertices.emplace_back(radius * n.x(), y, radius * n.z());
      m.normals.push_back(radial_normals ? n : cap_normal);
    }
    return first;
  };
  const Eigen::Vector3f unused = Eigen::Vector3f::Zero();  // side rings use radial normals
  const std::uint32_t bottom = ring(0, true, unused), top = ring(height, true, unused);
  for (std::uint32_t i = 0; i < kSides; ++i) {
    const std::uint32_t j = (i + 1) % kSides;
    m.triangles.push_back({bottom + i, bottom + j, top + j});
    m.triangles.push_back({bottom + i, top + j, top + i});
  }
  const std::uint32_t top_cap = ring(height, false, Eigen::Vector3f::UnitY());
  const std::uint32_t bottom_cap = ring(0, false, -Eigen::Vector3f::UnitY());
  const auto top_centre = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.emplace_back(0, height, 0);
  m.normals.push_back(Eigen::Vector3f::UnitY());
  m.vertices.emplace_back(0, 0, 0);
  m.normals.push_back(-Eigen::Vector3f::UnitY());
  for (std::uint32_t i = 0; i < kSides; ++i) {
    const std::uint32_t j = (i + 1) % kSides;
    m.triangles.push_back({top_centre, top_cap + i, top_cap + j});
    m.triangles.push_back({top_centre + 1, bottom_cap + j, bottom_cap + i});
  }
  return m;
}

TriangleMesh imported_mesh(const Occluder& occ, const fs::path& base_dir) {
  const fs::path file = occ.mesh.is_absolute() ? occ.mesh : base_dir / occ.mesh;
  const std::string what = "occluder '" + occ.name + "': mesh " + file.string();
  if (!fs::exists(file)) throw Error(what + ": file not found");
  Assimp::Importer importer;
  // Lines and points are split off by SortByPType and then ignored.
  const aiScene* scene =
      importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_PreTransformVertices |
                                           aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
  if (!scene || !scene->mRootNode) throw Error(what + ": " + importer.GetErrorString());
  TriangleMesh m;
  bool all_have_normals = true;
  for (unsigned mi = 0; mi < scene->mNumMeshes; ++mi) {
    const aiMesh* mesh = scene->mMeshes[mi];
    if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
    const auto base = static_cast<std::uint32_t>(m.vertices.size());
    all_have_normals = all_have_normals && mesh->HasNormals();
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      m.vertices.emplace_back(p.x, p.y, p.z);
      if (mesh->HasNormals()) {
        const aiVector3D& n = mesh->mNormals[v];
        m.normals.emplace_back(n.x, n.y, n.z);
      }
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      m.triangles.push_back(
          {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
    }
  }
  if (m.triangles.empty()) throw Error(what + ": holds no triangles");
  if (!all_have_normals) m.normals.clear();
  Eigen::Vector3f lo = m.vertices[0], hi = m.vertices[0];
  for (const auto& v : m.vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  const Eigen::Vector3f base_centre(0.5f * (lo.x() + hi.x()), lo.y(), 0.5f * (lo.z() + hi.z()));
  const auto scale = static_cast<float>(occ.mesh_scale);
  for (auto& v : m.vertices) v = scale * (v - base_centre);
  for (auto& n : m.normals) n.normalize();
  return m;
}

}  // namespace

std::vector<RoomSurface> room_surfaces(const Room& room) {
  const float x = 0.5f * static_cast<float>(room.size.x());
  const float y = static_cast<float>(room.size.y());
  const float z = 0.5f * static_cast<float>(room.size.z());
  const Eigen::Vector3f p[8] = {{-x, 0, -z}, {x, 0, -z}, {x, y, -z}, {-x, y, -z},
                                {-x, 0, z},  {x, 0, z},  {x, y, z},  {-x, y, z}};
  std::vector<RoomSurface> out(6);
  // Counter-clockwise seen from inside the room; image v of a wall texture runs down the wall.
  add_quad(out[0].mesh, p[0], p[4], p[5], p[1]);  // floor
  out[0].floor = true;
  add_quad(out[1].mesh, p[3], p[2], p[6], p[7]);  // ceiling
  add_quad(out[2].mesh, p[0], p[1], p[2], p[3]);  // wall z = -z
  add_quad(out[3].mesh, p[5], p[4], p[7], p[6]);  // wall z = +z
  add_quad(out[4].mesh, p[4], p[0], p[3], p[7]);  // wall x = -x
  add_quad(out[5].mesh, p[1], p[5], p[6], p[2]);  // wall x = +x
  for (int i = 2; i < 6; ++i) out[i].tex_v = -Eigen::Vector3f::UnitY();
  out[4].tex_u = out[5].tex_u = Eigen::Vector3f::UnitZ();
  return out;
}

TriangleMesh occluder_mesh(const Occluder& occ, const fs::path& base_dir) {
  TriangleMesh m;
  switch (occ.kind) {
    case Occluder::Kind::box:
      m = box_mesh(occ.size.cast<float>());
      break;
    case Occluder::Kind::cylinder:
      m = cylinder_mesh(0.5f * static_cast<float>(occ.size.x()), static_cast<float>(occ.size.y()));
      break;
    case Occluder::Kind::mesh:
      m = imported_mesh(occ, base_dir);
      break;
  }
  const Eigen::Matrix3f yaw =
      Eigen::AngleAxisf(static_cast<float>(occ.yaw_rad), Eigen::Vector3f::UnitY()).matrix();
  const Eigen::Vector3f at = occ.position.cast<float>();
  for (auto& v : m.vertices) v = yaw * v + at;
  for (auto& n : m.normals) n = yaw * n;
  return m;
}

}  // namespace simcap
