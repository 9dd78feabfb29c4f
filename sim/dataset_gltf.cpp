#include "sim/dataset_gltf.h"

#include <map>

#include "core/calibration.h"
#include "core/csv.h"
#include "core/error.h"
#include "models/body_gltf.h"
#include "models/body_source.h"
#include "scenes/scene.h"
#include "sim/scene_meshes.h"

namespace simcap {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

// Per frame and joint (as the tables name it): the rotation and the position.
struct TruthTables {
  std::map<std::pair<int, std::string>, Eigen::Quaterniond> rotation;
  std::map<std::pair<int, std::string>, Eigen::Vector3d> position;
  int frames = 0;
};

TruthTables read_truth(const fs::path& dataset) {
  TruthTables t;
  CsvReader angles(dataset / "gt" / "angles.csv", {"frame", "joint", "qw", "qx", "qy", "qz"});
  while (angles.next()) {
    const int f = static_cast<int>(angles.integer(0));
    t.rotation[{f, angles.text(1)}] =
        Eigen::Quaterniond(angles.number(2), angles.number(3), angles.number(4), angles.number(5));
    t.frames = std::max(t.frames, f + 1);
  }
  CsvReader joints(dataset / "gt" / "joints3d.csv", {"frame", "joint", "x", "y", "z"});
  while (joints.next()) {
    t.position[{static_cast<int>(joints.integer(0)), joints.text(1)}] = {
        joints.number(2), joints.number(3), joints.number(4)};
  }
  return t;
}

void add_static_mesh(GltfBuilder& gltf, const std::string& name, const TriangleMesh& mesh,
                     const Eigen::Vector3f& colour) {
  GltfBuilder::Vertices v;
  v.positions = mesh.vertices;
  v.normals = mesh.normals.empty() ? vertex_normals(mesh.vertices, mesh.triangles) : mesh.normals;
  GltfBuilder::Primitive p;
  for (const auto& t : mesh.triangles) p.indices.insert(p.indices.end(), t.begin(), t.end());
  p.material = gltf.add_material(name, colour);
  GltfBuilder::Node node;
  node.name = name;
  node.mesh = gltf.add_mesh(name, v, {p});
  gltf.add_node(node);
}

void add_camera(GltfBuilder& gltf, const Camera& cam) {
  const double fx = cam.K(0, 0), fy = cam.K(1, 1);
  GltfBuilder::Node node;
  node.name = cam.name;
  node.camera = gltf.add_camera(cam.name, 2 * std::atan(0.5 * cam.height / fy),
                                (cam.width * fy) / (cam.height * fx), 0.05, 100.0);
  node.translation = cam.centre();
  // OpenCV's camera looks down +Z with +Y down; glTF's down -Z with +Y up.
  node.rotation = Eigen::Quaterniond(cam.R.transpose() * Eigen::Vector3d(1, -1, -1).asDiagonal());
  auto rows = [](const Eigen::MatrixXd& m) {
    Json out = Json::array();
    for (int r = 0; r < m.rows(); ++r) {
      Json row = Json::array();
      for (int c = 0; c < m.cols(); ++c) row.push_back(m(r, c));
      out.push_back(row);
    }
    return out;
  };
  node.extras = {{"simcap_calibration",
                  {{"width", cam.width},
                   {"height", cam.height},
                   {"K", rows(cam.K)},
                   {"dist", {cam.dist[0], cam.dist[1], cam.dist[2], cam.dist[3], cam.dist[4]}},
                   {"R", rows(cam.R)},
                   {"t", {cam.t.x(), cam.t.y(), cam.t.z()}}}}};
  gltf.add_node(node);
}

}  // namespace

DatasetGltfSummary export_dataset_gltf(const fs::path& dataset, const fs::path& out) {
  const Scene scene = load_scene(dataset / "scene.yaml");
  const std::vector<Camera> cameras =
      read_opencv_calibration(dataset / "calibration" / "opencv.yaml");
  const TruthTables truth = read_truth(dataset);
  if (truth.frames == 0) throw Error((dataset / "gt" / "angles.csv").string() + ": no frames");

  GltfBuilder gltf;
  for (const RoomSurface& s : room_surfaces(scene.room)) {
    add_static_mesh(gltf, s.floor ? "floor" : "wall", s.mesh,
                    s.floor ? scene.room.floor_color : scene.room.wall_color);
  }
  for (const Occluder& o : scene.occluders) {
    add_static_mesh(gltf, o.name, occluder_mesh(o, scene.source.parent_path()), o.color);
  }
  for (const Camera& cam : cameras) add_camera(gltf, cam);

  std::vector<GltfBuilder::Channel> channels;
  for (size_t a = 0; a < scene.actors.size(); ++a) {
    const Actor& actor = scene.actors[a];
    const Body body = build_body(actor.body);
    const Skeleton& s = body.skeleton;
    const std::string prefix = scene.actors.size() > 1 && a > 0 ? actor.name + "/" : "";
    std::vector<Pose> frames;
    for (int f = 0; f < truth.frames; ++f) {
      Pose p = Pose::neutral(s);
      for (int j = 0; j < s.size(); ++j) {
        if (s[j].is_site) continue;
        const auto it = truth.rotation.find({f, prefix + s[j].name});
        if (it == truth.rotation.end()) {
          throw Error((dataset / "gt" / "angles.csv").string() + ": no rotation of '" + prefix +
                      s[j].name + "' in frame " + std::to_string(f) + " (the scene's actor '" +
                      actor.name + "' has that joint)");
        }
        p.rotations[j] = it->second;
      }
      const auto root = truth.position.find({f, prefix + s[0].name});
      if (root == truth.position.end()) {
        throw Error((dataset / "gt" / "joints3d.csv").string() + ": no position of '" + prefix +
                    s[0].name + "' in frame " + std::to_string(f));
      }
      p.root_position = root->second;
      frames.push_back(std::move(p));
    }
    const GltfBody g = add_gltf_body(gltf, actor.name, s, body.mesh, actor.colors, frames[0]);
    const auto c = gltf_motion_channels(g, s, frames, scene.render.fps);
    channels.insert(channels.end(), c.begin(), c.end());
  }
  gltf.add_animation("dataset", channels);
  gltf.write(out);
  return {static_cast<int>(cameras.size()), static_cast<int>(scene.actors.size()), truth.frames};
}

}  // namespace simcap
