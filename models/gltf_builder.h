// A binary glTF 2.0 (.glb) writer for what simcap exports: meshes with materials and skins,
// a node tree, perspective cameras and animations. Assimp's exporter writes no cameras, so
// simcap assembles the JSON and the binary buffer itself (readers: Blender, three.js, Assimp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace simcap {

class GltfBuilder {
 public:
  struct Primitive {
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise from outside
    int material = -1;
  };
  // Vertex data shared by a mesh's primitives. joints/weights (four influences per vertex,
  // skin joint indices and weights summing to 1) are empty for a rigid mesh.
  struct Vertices {
    std::vector<Eigen::Vector3f> positions;
    std::vector<Eigen::Vector3f> normals;  // empty: the reader shades flat
    std::vector<std::array<std::uint16_t, 4>> joints;
    std::vector<std::array<float, 4>> weights;
  };
  struct Node {
    std::string name;
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
    int mesh = -1, skin = -1, camera = -1;
    nlohmann::ordered_json extras;  // application data, written when not null
  };
  struct Channel {
    int node = 0;
    bool rotation = false;                // rotation (quaternions) or translation
    std::vector<float> times;             // seconds, increasing
    std::vector<Eigen::Vector4f> values;  // x y z w for rotations; x y z (w unused) otherwise
  };

  // `srgb` is the colour as simcap's scenes state it; glTF's base colour is linear.
  int add_material(const std::string& name, const Eigen::Vector3f& srgb, bool double_sided = false);
  int add_mesh(const std::string& name, const Vertices& vertices,
               const std::vector<Primitive>& primitives);
  // A node under `parent` (-1: a root of the scene). Returns its index.
  int add_node(const Node& node, int parent = -1);
  // `joints` are node indices; inverse bind matrices take world to each joint's bind frame.
  int add_skin(const std::string& name, const std::vector<int>& joints,
               const std::vector<Eigen::Matrix4f>& inverse_binds, int skeleton_root);
  // Perspective camera looking down its node's -Z with +Y up; yfov in radians, aspect = w / h.
  int add_camera(const std::string& name, double yfov, double aspect, double znear, double zfar);
  void add_animation(const std::string& name, const std::vector<Channel>& channels);

  // The whole file: 12-byte header, JSON chunk, binary chunk.
  std::string glb() const;
  // Writes glb() atomically.
  void write(const std::filesystem::path& path) const;

 private:
  // Appends `bytes` to the binary buffer (4-byte aligned) as a buffer view; returns its index.
  int add_view(const void* bytes, size_t size, std::optional<int> target);
  int add_accessor(int view, int component_type, size_t count, const char* type,
                   const nlohmann::ordered_json& min = nullptr,
                   const nlohmann::ordered_json& max = nullptr);

  nlohmann::ordered_json json_ = {{"asset", {{"version", "2.0"}, {"generator", "simcap"}}}};
  std::vector<std::uint8_t> bin_;
  std::vector<std::vector<int>> children_;
  std::vector<int> roots_;
};

}  // namespace simcap
