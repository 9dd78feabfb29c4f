#include "models/rigged_mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <assimp/Importer.hpp>
#include <cmath>
#include <map>

#include "core/error.h"
#include "models/imported_body.h"

namespace simcap {
namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d e;
  e << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return e;
}

bool is_site_name(const std::string& hanim) {
  return hanim == "skull_tip" || hanim == "l_hand_tip" || hanim == "r_hand_tip" ||
         hanim == "l_toe_tip" || hanim == "r_toe_tip";
}

class Reader {
 public:
  Reader(const std::filesystem::path& path, const RiggedMeshOptions& options)
      : path_(path), options_(options) {}

  Body read() {
    Assimp::Importer importer;
    const aiScene* scene =
        importer.ReadFile(path_.string(), aiProcess_Triangulate | aiProcess_SortByPType |
                                              aiProcess_ValidateDataStructure);
    if (!scene || !scene->mRootNode) {
      fail(std::string("Assimp cannot read it: ") + importer.GetErrorString());
    }
    index_nodes(scene->mRootNode, Eigen::Matrix4d::Identity());
    collect_bones(scene);
    if (bind_.empty()) fail("no mesh of the file has bones (expected a rigged mesh)");

    std::vector<std::string> names;
    for (const auto& [name, node] : nodes_) names.push_back(name);
    naming_ =
        options_.naming == JointNaming::automatic ? detect_joint_naming(names) : options_.naming;
    const aiNode* root = nullptr;
    for (const auto& [name, node] : nodes_) {
      if (hanim_joint_name(naming_, name) == "humanoid_root") root = node;
    }
    if (!root) {
      fail("no bone maps to humanoid_root under the " +
           std::string(name_of(kJointNamings, naming_)) + " joint names (models/joint_names.md)");
    }
    SkinnedSkeleton found;
    add_joints(root, -1, found.skeleton);
    add_skin(scene, found);
    place(found);
    Body body = finish_imported_body(std::move(found), path_);
    body.notes.insert(body.notes.begin(),
                      "joint names: " + std::string(name_of(kJointNamings, naming_)) + "; " +
                          std::to_string(folded_) + " bones folded into named ancestors");
    return body;
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw_input_error(path_, 0, "", message);
  }

  void index_nodes(const aiNode* node, const Eigen::Matrix4d& parent_global) {
    const Eigen::Matrix4d global = parent_global * to_eigen(node->mTransformation);
    global_[node] = global;
    order_.push_back(node);
    nodes_.emplace(node->mName.C_Str(), node);
    for (unsigned i = 0; i < node->mNumChildren; ++i) index_nodes(node->mChildren[i], global);
  }

  // Bind transforms (world) of the bones, from each skinned mesh's node and offset matrices.
  void collect_bones(const aiScene* scene) {
    for (const aiNode* node : order_) {
      const Eigen::Matrix4d& global = global_.at(node);
      for (unsigned k = 0; k < node->mNumMeshes; ++k) {
        const aiMesh* mesh = scene->mMeshes[node->mMeshes[k]];
        for (unsigned b = 0; b < mesh->mNumBones; ++b) {
          const aiBone* bone = mesh->mBones[b];
          bind_.emplace(bone->mName.C_Str(), global * to_eigen(bone->mOffsetMatrix).inverse());
        }
      }
    }
  }

  // A node's bind transform: its bone's, or its parent's composed with its own local transform.
  Eigen::Matrix4d bind_of(const aiNode* node) const {
    const auto it = bind_.find(node->mName.C_Str());
    if (it != bind_.end()) return it->second;
    if (!node->mParent) return global_.at(node);
    return bind_of(node->mParent) * to_eigen(node->mTransformation);
  }

  void add_joints(const aiNode* node, int parent, Skeleton& skeleton) {
    const std::string name = node->mName.C_Str();
    const std::string hanim = hanim_joint_name(naming_, name);
    int self = parent;
    if (!hanim.empty()) {
      if (const auto it = source_of_.find(hanim); it != source_of_.end()) {
        fail("bones '" + it->second + "' and '" + name + "' both map to H-Anim joint '" + hanim +
             "'");
      }
      source_of_[hanim] = name;
      const bool site = is_site_name(hanim);
      if (!site && parent >= 0 && skeleton[parent].is_site) {
        fail("bone '" + name + "' (" + hanim + ") hangs below end site '" + skeleton[parent].name +
             "'");
      }
      self = skeleton.add({hanim, "", parent, bind_of(node).topRightCorner<3, 1>(), site});
    } else if (bind_.count(name)) {
      ++folded_;
    }
    joint_of_node_[name] = self;
    for (unsigned i = 0; i < node->mNumChildren; ++i)
      add_joints(node->mChildren[i], self, skeleton);
  }

  void add_skin(const aiScene* scene, SkinnedSkeleton& found) {
    for (const aiNode* node : order_) {
      const Eigen::Matrix4d& global = global_.at(node);
      for (unsigned k = 0; k < node->mNumMeshes; ++k) {
        const aiMesh* mesh = scene->mMeshes[node->mMeshes[k]];
        if (mesh->mNumBones == 0 || !(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;
        // Only the vertices the mesh's faces use: glTF primitives that share one vertex array
        // arrive as meshes with the whole array each.
        std::vector<std::uint32_t> index(mesh->mNumVertices, ~0u);
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
          const aiFace& face = mesh->mFaces[f];
          if (face.mNumIndices != 3) continue;
          for (unsigned c = 0; c < 3; ++c) {
            const unsigned v = face.mIndices[c];
            if (index[v] != ~0u) continue;
            index[v] = static_cast<std::uint32_t>(found.vertices.size());
            const aiVector3D& p = mesh->mVertices[v];
            found.vertices.push_back(
                (global * Eigen::Vector4d(p.x, p.y, p.z, 1)).head<3>().cast<float>());
          }
        }
        found.weights.resize(found.vertices.size());
        for (unsigned b = 0; b < mesh->mNumBones; ++b) {
          const aiBone* bone = mesh->mBones[b];
          const auto it = joint_of_node_.find(bone->mName.C_Str());
          if (it == joint_of_node_.end() || it->second < 0) {
            fail("bone '" + std::string(bone->mName.C_Str()) +
                 "' lies outside the skeleton under humanoid_root, yet weights the skin");
          }
          for (unsigned w = 0; w < bone->mNumWeights; ++w) {
            const aiVertexWeight& vw = bone->mWeights[w];
            if (vw.mVertexId >= mesh->mNumVertices) {
              fail("bone '" + std::string(bone->mName.C_Str()) + "' weights vertex " +
                   std::to_string(vw.mVertexId) + " of a mesh of " +
                   std::to_string(mesh->mNumVertices));
            }
            if (index[vw.mVertexId] != ~0u) {
              found.weights[index[vw.mVertexId]].emplace_back(it->second, vw.mWeight);
            }
          }
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
          const aiFace& face = mesh->mFaces[f];
          if (face.mNumIndices != 3) continue;
          found.triangles.push_back(
              {index[face.mIndices[0]], index[face.mIndices[1]], index[face.mIndices[2]]});
        }
      }
    }
  }

  // Metres, +Y up, the left hip towards +X, feet on the floor.
  void place(SkinnedSkeleton& found) const {
    if (found.vertices.empty()) fail("the skinned meshes have no triangles");
    float low = INFINITY, high = -INFINITY;
    for (const auto& v : found.vertices) {
      low = std::min(low, v.y());
      high = std::max(high, v.y());
    }
    double unit = options_.metres_per_unit;
    if (unit <= 0) {
      double best = INFINITY;
      for (const double candidate : {1.0, 0.01, 0.001, 0.0254}) {
        const double misfit = std::abs(std::log((high - low) * candidate / 1.7));
        if (misfit < best) {
          best = misfit;
          unit = candidate;
        }
      }
    }
    Skeleton& s = found.skeleton;
    const int root = s.require("humanoid_root");
    const int head = s.find("skullbase");
    if (head >= 0 && !(s[head].center.y() > s[root].center.y())) {
      fail("the head (skullbase) is not above humanoid_root: expected +Y up");
    }
    Eigen::Vector3d lateral = Eigen::Vector3d::UnitX();
    if (s.find("l_hip") >= 0 && s.find("r_hip") >= 0) {
      lateral = s[s.require("l_hip")].center - s[s.require("r_hip")].center;
      lateral.y() = 0;
    }
    // R_y(a) takes (x, 0, z) to (x cos a + z sin a, 0, z cos a - x sin a): on +X for this a.
    const double yaw = lateral.norm() > 0 ? std::atan2(lateral.z(), lateral.x()) : 0.0;
    const Eigen::Matrix3d turn =
        unit * Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const double lift = -unit * low;
    auto moved = [&](const Eigen::Vector3d& p) {
      Eigen::Vector3d q = turn * p;
      q.y() += lift;
      return q;
    };
    Skeleton placed;
    for (const Joint& j : s.joints()) {
      Joint copy = j;
      copy.center = moved(j.center);
      placed.add(std::move(copy));
    }
    s = std::move(placed);
    for (auto& v : found.vertices) v = moved(v.cast<double>()).cast<float>();
  }

  std::filesystem::path path_;
  RiggedMeshOptions options_;
  JointNaming naming_ = JointNaming::hanim;
  std::map<const aiNode*, Eigen::Matrix4d> global_;
  std::vector<const aiNode*> order_;  // depth first, children in file order
  std::multimap<std::string, const aiNode*> nodes_;
  std::map<std::string, Eigen::Matrix4d> bind_;
  std::map<std::string, std::string> source_of_;  // H-Anim joint -> bone
  std::map<std::string, int> joint_of_node_;      // node -> joint it moves with (-1: none)
  int folded_ = 0;
};

}  // namespace

Body read_rigged_mesh(const std::filesystem::path& path, const RiggedMeshOptions& options) {
  return Reader(path, options).read();
}

}  // namespace simcap
