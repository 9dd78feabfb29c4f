#include "core/dataset_actors.h"

#include <yaml-cpp/yaml.h>

#include <fstream>

#include "core/error.h"

namespace simcap {
namespace fs = std::filesystem;

std::vector<std::string> read_dataset_actors(const fs::path& dataset) {
  const fs::path path = dataset / "scene.yaml";
  if (!fs::is_regular_file(path)) return {};
  std::vector<std::string> names;
  try {
    const YAML::Node actors = YAML::LoadFile(path.string())["actors"];
    if (!actors) return {};
    if (!actors.IsSequence())
      throw_input_error(path, actors.Mark().line + 1, "actors", "not a list");
    for (size_t i = 0; i < actors.size(); ++i) {
      const YAML::Node name = actors[i]["name"];
      names.push_back(name ? name.as<std::string>() : "actor" + std::to_string(i));
    }
  } catch (const YAML::Exception& e) {
    throw_input_error(path, e.mark.line + 1, "actors", e.msg);
  }
  return names;
}

int find_actor(const std::vector<std::string>& actors, const std::string& name,
               const std::string& what) {
  if (name.empty()) return 0;
  for (size_t i = 0; i < actors.size(); ++i) {
    if (actors[i] == name) return static_cast<int>(i);
  }
  std::string list;
  for (const std::string& a : actors) list += (list.empty() ? "" : ", ") + a;
  throw Error(what + " " + name + ": no such actor; the dataset has " +
              (actors.empty() ? std::string("no scene.yaml naming its actors") : list));
}

std::string actor_joint_prefix(const std::vector<std::string>& actors, int index) {
  return actors.size() > 1 && index > 0 ? actors.at(index) + "/" : "";
}

JointTrack actor_joints(const JointTrack& truth, const std::vector<std::string>& actors,
                        int index) {
  if (actors.size() <= 1) return truth;
  const std::string prefix = actor_joint_prefix(actors, index);
  const auto other_actor = [&](const std::string& joint) {
    for (size_t a = 1; a < actors.size(); ++a) {
      if (joint.starts_with(actors[a] + "/")) return true;
    }
    return false;
  };
  std::vector<int> kept;
  JointTrack out;
  for (size_t j = 0; j < truth.joints.size(); ++j) {
    const std::string& name = truth.joints[j];
    const bool mine = prefix.empty() ? !other_actor(name) : name.starts_with(prefix);
    if (!mine) continue;
    kept.push_back(static_cast<int>(j));
    out.joints.push_back(name.substr(prefix.size()));
  }
  for (size_t f = 0; f < truth.frames.size(); ++f) {
    std::vector<Eigen::Vector3d> p;
    p.reserve(kept.size());
    for (const int j : kept) p.push_back(truth.positions[f][j]);
    out.add_frame(truth.frames[f], std::move(p));
  }
  return out;
}

int actor_mask_label(const std::vector<std::string>& actors, int index) {
  return actors.size() > 1 ? index + 1 : 255;
}

std::string read_track_actor(const fs::path& track) {
  const fs::path path = track / kTrackActorFile;
  if (!fs::is_regular_file(path)) return {};
  std::ifstream in(path);
  std::string name;
  std::getline(in, name);
  if (name.empty()) throw_input_error(path, 1, "", "empty; expected the tracked actor's name");
  return name;
}

}  // namespace simcap
