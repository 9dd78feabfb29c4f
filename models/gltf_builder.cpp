#include "models/gltf_builder.h"

#include <cmath>
#include <cstring>

#include "core/atomic_file.h"
#include "core/error.h"

namespace simcap {
namespace {

using Json = nlohmann::ordered_json;

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// IEC 61966-2-1 sRGB decoding.
float linear_of(float srgb) {
  return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
}

template <class T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

}  // namespace

int GltfBuilder::add_view(const void* bytes, size_t size, std::optional<int> target) {
  while (bin_.size() % 4) bin_.push_back(0);
  const size_t offset = bin_.size();
  const auto* p = static_cast<const std::uint8_t*>(bytes);
  bin_.insert(bin_.end(), p, p + size);
  Json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
  if (target) view["target"] = *target;
  json_["bufferViews"].push_back(view);
  return static_cast<int>(json_["bufferViews"].size()) - 1;
}

int GltfBuilder::add_accessor(int view, int component_type, size_t count, const char* type,
                              const Json& min, const Json& max) {
  Json a = {
      {"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
  if (!min.is_null()) a["min"] = min;
  if (!max.is_null()) a["max"] = max;
  json_["accessors"].push_back(a);
  return static_cast<int>(json_["accessors"].size()) - 1;
}

int GltfBuilder::add_material(const std::string& name, const Eigen::Vector3f& srgb,
                              bool double_sided) {
  json_["materials"].push_back(
      {{"name", name},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {linear_of(srgb.x()), linear_of(srgb.y()), linear_of(srgb.z()), 1.0f}},
         {"metallicFactor", 0.0},
         {"roughnessFactor", 1.0}}},
       {"doubleSided", double_sided}});
  return static_cast<int>(json_["materials"].size()) - 1;
}

int GltfBuilder::add_mesh(const std::string& name, const Vertices& v,
                          const std::vector<Primitive>& primitives) {
  const size_t n = v.positions.size();
  if (n == 0) throw Error("glTF: mesh '" + name + "' has no vertices");
  if ((!v.normals.empty() && v.normals.size() != n) || v.joints.size() != v.weights.size() ||
      (!v.joints.empty() && v.joints.size() != n)) {
    throw Error("glTF: mesh '" + name + "' has attributes of different lengths");
  }
  Eigen::Vector3f lo = v.positions[0], hi = v.positions[0];
  for (const auto& p : v.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  Json attributes;
  attributes["POSITION"] =
      add_accessor(add_view(v.positions.data(), n * sizeof(Eigen::Vector3f), kArrayBuffer), kFloat,
                   n, "VEC3", {lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()});
  if (!v.normals.empty()) {
    attributes["NORMAL"] = add_accessor(
        add_view(v.normals.data(), n * sizeof(Eigen::Vector3f), kArrayBuffer), kFloat, n, "VEC3");
  }
  if (!v.joints.empty()) {
    attributes["JOINTS_0"] =
        add_accessor(add_view(v.joints.data(), n * 8, kArrayBuffer), kUnsignedShort, n, "VEC4");
    attributes["WEIGHTS_0"] =
        add_accessor(add_view(v.weights.data(), n * 16, kArrayBuffer), kFloat, n, "VEC4");
  }
  Json prims = Json::array();
  for (const Primitive& p : primitives) {
    for (const std::uint32_t i : p.indices) {
      if (i >= n) throw Error("glTF: mesh '" + name + "' indexes a vertex it does not have");
    }
    Json prim = {{"attributes", attributes},
                 {"indices", add_accessor(add_view(p.indices.data(), p.indices.size() * 4,
                                                   kElementArrayBuffer),
                                          kUnsignedInt, p.indices.size(), "SCALAR")},
                 {"mode", 4}};
    if (p.material >= 0) prim["material"] = p.material;
    prims.push_back(prim);
  }
  json_["meshes"].push_back({{"name", name}, {"primitives", prims}});
  return static_cast<int>(json_["meshes"].size()) - 1;
}

int GltfBuilder::add_node(const Node& node, int parent) {
  Json n = {{"name", node.name}};
  if (!node.translation.isZero()) {
    n["translation"] = {node.translation.x(), node.translation.y(), node.translation.z()};
  }
  const Eigen::Quaterniond q = node.rotation.normalized();
  if (!q.coeffs().isApprox(Eigen::Quaterniond::Identity().coeffs())) {
    n["rotation"] = {q.x(), q.y(), q.z(), q.w()};
  }
  if (node.mesh >= 0) n["mesh"] = node.mesh;
  if (node.skin >= 0) n["skin"] = node.skin;
  if (node.camera >= 0) n["camera"] = node.camera;
  if (!node.extras.is_null()) n["extras"] = node.extras;
  json_["nodes"].push_back(n);
  const int index = static_cast<int>(json_["nodes"].size()) - 1;
  children_.emplace_back();
  if (parent < 0) {
    roots_.push_back(index);
  } else {
    children_.at(parent).push_back(index);
  }
  return index;
}

int GltfBuilder::add_skin(const std::string& name, const std::vector<int>& joints,
                          const std::vector<Eigen::Matrix4f>& inverse_binds, int skeleton_root) {
  if (joints.size() != inverse_binds.size()) {
    throw Error("glTF: skin '" + name + "' has as many inverse bind matrices as joints");
  }
  // glTF matrices are column-major, as Eigen's.
  const int matrices = add_accessor(
      add_view(inverse_binds.data(), inverse_binds.size() * sizeof(Eigen::Matrix4f), std::nullopt),
      kFloat, inverse_binds.size(), "MAT4");
  json_["skins"].push_back({{"name", name},
                            {"inverseBindMatrices", matrices},
                            {"skeleton", skeleton_root},
                            {"joints", joints}});
  return static_cast<int>(json_["skins"].size()) - 1;
}

int GltfBuilder::add_camera(const std::string& name, double yfov, double aspect, double znear,
                            double zfar) {
  json_["cameras"].push_back(
      {{"name", name},
       {"type", "perspective"},
       {"perspective",
        {{"yfov", yfov}, {"aspectRatio", aspect}, {"znear", znear}, {"zfar", zfar}}}});
  return static_cast<int>(json_["cameras"].size()) - 1;
}

void GltfBuilder::add_animation(const std::string& name, const std::vector<Channel>& channels) {
  Json samplers = Json::array(), targets = Json::array();
  for (const Channel& c : channels) {
    if (c.times.empty() || c.times.size() != c.values.size()) {
      throw Error("glTF: animation '" + name + "' has a channel without matching keys");
    }
    const int input =
        add_accessor(add_view(c.times.data(), c.times.size() * 4, std::nullopt), kFloat,
                     c.times.size(), "SCALAR", {c.times.front()}, {c.times.back()});
    std::vector<float> values;
    for (const Eigen::Vector4f& v : c.values) {
      for (int k = 0; k < (c.rotation ? 4 : 3); ++k) values.push_back(v[k]);
    }
    const int output = add_accessor(add_view(values.data(), values.size() * 4, std::nullopt),
                                    kFloat, c.values.size(), c.rotation ? "VEC4" : "VEC3");
    samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
    targets.push_back(
        {{"sampler", samplers.size() - 1},
         {"target", {{"node", c.node}, {"path", c.rotation ? "rotation" : "translation"}}}});
  }
  json_["animations"].push_back({{"name", name}, {"channels", targets}, {"samplers", samplers}});
}

std::string GltfBuilder::glb() const {
  Json json = json_;
  for (size_t i = 0; i < children_.size(); ++i) {
    if (!children_[i].empty()) json["nodes"][i]["children"] = children_[i];
  }
  json["scene"] = 0;
  json["scenes"] = {{{"nodes", roots_}}};
  if (!bin_.empty()) json["buffers"] = {{{"byteLength", bin_.size()}}};
  std::string text = json.dump();
  while (text.size() % 4) text += ' ';
  std::string bin(bin_.begin(), bin_.end());
  while (bin.size() % 4) bin += '\0';
  std::string out;
  put<std::uint32_t>(out, 0x46546C67);  // "glTF"
  put<std::uint32_t>(out, 2);
  put<std::uint32_t>(
      out, static_cast<std::uint32_t>(12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size())));
  put<std::uint32_t>(out, static_cast<std::uint32_t>(text.size()));
  put<std::uint32_t>(out, 0x4E4F534A);  // "JSON"
  out += text;
  if (!bin.empty()) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(bin.size()));
    put<std::uint32_t>(out, 0x004E4942);  // "BIN"
    out += bin;
  }
  return out;
}

void GltfBuilder::write(const std::filesystem::path& path) const {
  write_text_atomic(path, glb());
}

}  // namespace simcap
