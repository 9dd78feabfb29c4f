#include "validate/keypoint_truth.h"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/calibration.h"
#include "core/csv.h"
#include "core/dataset_actors.h"
#include "core/error.h"
#include "core/joint_table.h"
#include "core/joint_track.h"

namespace simcap {
namespace fs = std::filesystem;

namespace {

using Json = nlohmann::json;

// Where each layout keypoint's truth comes from, for every actor: (actor, keypoint) pairs by the
// name the table gives the point ("<actor>/" prefixed after the first actor).
using Needs = std::map<std::string, std::vector<std::pair<int, int>>>;

Needs needs_of(const KeypointLayout& layout, TruthKind kind,
               const std::vector<std::string>& actors) {
  Needs needs;
  for (size_t a = 0; a < actors.size(); ++a) {
    const std::string prefix = actor_joint_prefix(actors, static_cast<int>(a));
    for (int k = 0; k < layout.size(); ++k) {
      if (layout.keypoints[k].truth != kind) continue;
      needs[prefix + std::string(layout.keypoints[k].truth_name)].emplace_back(static_cast<int>(a),
                                                                               k);
    }
  }
  return needs;
}

const Json& member(const Json& object, const char* name, const fs::path& file,
                   const std::string& field) {
  if (!object.is_object() || !object.contains(name)) {
    throw_input_error(file, 0, field, std::string("has no ") + name);
  }
  return object[name];
}

const Json& array_member(const Json& object, const char* name, const fs::path& file) {
  const Json& a = member(object, name, file, "");
  if (!a.is_array()) throw_input_error(file, 0, name, "expected an array");
  return a;
}

int frame_count(const Json& coco, const fs::path& file) {
  int last = -1;
  const Json& images = array_member(coco, "images", file);
  for (size_t i = 0; i < images.size(); ++i) {
    const Json& f = member(images[i], "frame", file, "images[" + std::to_string(i) + "]");
    if (!f.is_number_integer() || f.get<long>() < 0 || f.get<long>() > 10'000'000) {
      throw_input_error(file, 0, "images[" + std::to_string(i) + "].frame",
                        "expected a frame number");
    }
    last = std::max(last, f.get<int>());
  }
  if (last < 0) throw_input_error(file, 0, "images", "no images");
  return last + 1;
}

void read_coco_truth(KeypointTruth& truth, const Json& coco, const fs::path& file) {
  const auto& cameras = truth.cameras();
  const auto& actors = truth.actors();
  const KeypointLayout& layout = keypoint_layout(truth.layout());
  const KeypointLayout& coco17 = keypoint_layout(KeypointLayoutId::coco17);
  std::map<long, std::pair<int, int>> images;  // id -> (frame, camera)
  const Json& list = array_member(coco, "images", file);
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string field = "images[" + std::to_string(i) + "]";
    const Json& cam = member(list[i], "camera", file, field);
    const auto c =
        std::find(cameras.begin(), cameras.end(), cam.is_string() ? cam.get<std::string>() : "");
    if (c == cameras.end())
      throw_input_error(file, 0, field + ".camera", "not a camera of the calibration");
    const Json& id = member(list[i], "id", file, field);
    if (!id.is_number_integer()) throw_input_error(file, 0, field + ".id", "expected an integer");
    images[id.get<long>()] = {list[i]["frame"].get<int>(), static_cast<int>(c - cameras.begin())};
  }
  const Json& annotations = array_member(coco, "annotations", file);
  for (size_t i = 0; i < annotations.size(); ++i) {
    const std::string field = "annotations[" + std::to_string(i) + "]";
    const Json& ann = annotations[i];
    const Json& id = member(ann, "image_id", file, field);
    const auto image = images.find(id.is_number_integer() ? id.get<long>() : -1);
    if (image == images.end())
      throw_input_error(file, 0, field + ".image_id", "not an image of the file");
    const Json& name = member(ann, "actor", file, field);
    const auto a =
        std::find(actors.begin(), actors.end(), name.is_string() ? name.get<std::string>() : "");
    if (a == actors.end())
      throw_input_error(file, 0, field + ".actor", "not an actor of scene.yaml");
    const Json& kp = member(ann, "keypoints", file, field);
    const Json& area = member(ann, "area", file, field);
    const Json& box = member(ann, "bbox", file, field);
    if (!box.is_array() || box.size() != 4 || !box[3].is_number()) {
      throw_input_error(file, 0, field + ".bbox", "expected [x, y, width, height]");
    }
    if (!kp.is_array() || kp.size() != 51 ||
        !std::all_of(kp.begin(), kp.end(), [](const Json& v) { return v.is_number(); })) {
      throw_input_error(file, 0, field + ".keypoints", "expected 51 numbers (17 keypoints x 3)");
    }
    if (!area.is_number() || area.get<double>() < 0)
      throw_input_error(file, 0, field + ".area", "expected a number >= 0");
    const Json* labels = ann.contains("visibility") ? &ann["visibility"] : nullptr;
    if (labels && (!labels->is_array() || labels->size() != 17)) {
      throw_input_error(file, 0, field + ".visibility", "expected 17 labels");
    }
    ActorView& view =
        truth.at(image->second.first, image->second.second, static_cast<int>(a - actors.begin()));
    view.annotated = true;
    view.area = area.get<double>();
    view.box_height = box[3].get<double>();
    for (int k = 0; k < layout.size(); ++k) {
      const LayoutKeypoint& lk = layout.keypoints[k];
      if (lk.truth != TruthKind::coco17_point) continue;
      const size_t j = static_cast<size_t>(coco17.index(lk.truth_name));
      TruthKeypoint& t = view.keypoints[k];
      t.known = true;
      t.pixel = {kp[3 * j].get<double>(), kp[3 * j + 1].get<double>()};
      const double v = kp[3 * j + 2].get<double>();
      if (labels) {
        const Json& l = (*labels)[j];
        const auto label = visibility_label_of(l.is_string() ? l.get<std::string>() : "");
        if (!label)
          throw_input_error(file, 0, field + ".visibility[" + std::to_string(j) + "]",
                            "expected visible, self_occluded, scene_occluded or out_of_frame");
        t.visibility = *label;
      } else {
        t.visibility = v == 2   ? VisibilityLabel::visible
                       : v == 0 ? VisibilityLabel::out_of_frame
                                : VisibilityLabel::missing;
      }
    }
  }
}

void read_joints2d_truth(KeypointTruth& truth, const fs::path& file) {
  const Needs needs =
      needs_of(keypoint_layout(truth.layout()), TruthKind::hanim_joint, truth.actors());
  if (needs.empty()) return;
  const auto& cameras = truth.cameras();
  CsvReader csv(file, {"frame", "camera", "joint", "u", "v", "depth", "visibility"});
  while (csv.next()) {
    const auto need = needs.find(csv.text(2));
    if (need == needs.end()) continue;
    const int frame = read_frame_number(csv, 0);
    if (frame >= truth.frames()) continue;
    const auto c = std::find(cameras.begin(), cameras.end(), csv.text(1));
    if (c == cameras.end()) csv.fail(1, "unknown camera '" + csv.text(1) + "'");
    const auto label = visibility_label_of(csv.text(6));
    if (!label) csv.fail(6, "expected visible, self_occluded, scene_occluded or out_of_frame");
    const Eigen::Vector2d pixel(csv.number(3), csv.number(4));
    for (const auto& [a, k] : need->second) {
      TruthKeypoint& t = truth.at(frame, static_cast<int>(c - cameras.begin()), a).keypoints[k];
      t = {true, pixel, *label};
    }
  }
}

void read_h36m_truth(KeypointTruth& truth, const fs::path& file,
                     const std::vector<Camera>& cameras) {
  const Needs needs =
      needs_of(keypoint_layout(truth.layout()), TruthKind::h36m17_point, truth.actors());
  if (needs.empty()) return;
  const JointTrack track = read_joint_track(file);
  for (const auto& [name, uses] : needs) {
    const int j = track.joint_index(name);
    if (j < 0) throw_input_error(file, 0, "joint", "no rows for " + name);
    for (size_t f = 0; f < track.frames.size(); ++f) {
      if (track.frames[f] >= truth.frames() || !track.positions[f][j].allFinite()) continue;
      for (size_t c = 0; c < cameras.size(); ++c) {
        const auto pixel = cameras[c].project(track.positions[f][j]);
        if (!pixel) continue;
        const bool inside = cameras[c].in_frustum(track.positions[f][j]);
        for (const auto& [a, k] : uses) {
          truth.at(track.frames[f], static_cast<int>(c), a).keypoints[k] = {
              true, *pixel, inside ? VisibilityLabel::missing : VisibilityLabel::out_of_frame};
        }
      }
    }
  }
}

}  // namespace

KeypointTruth::KeypointTruth(KeypointLayoutId layout, std::vector<std::string> cameras,
                             std::vector<std::string> actors, int frames)
    : layout_(layout), cameras_(std::move(cameras)), actors_(std::move(actors)), frames_(frames) {
  views_.resize(
      static_cast<size_t>(frames_) * cameras_.size() * actors_.size(),
      ActorView{false, 0.0, 0.0,
                std::vector<TruthKeypoint>(static_cast<size_t>(keypoint_layout(layout).size()))});
}

const ActorView& KeypointTruth::at(int frame, int camera, int actor) const {
  if (frame < 0 || frame >= frames_ || camera < 0 || camera >= static_cast<int>(cameras_.size()) ||
      actor < 0 || actor >= static_cast<int>(actors_.size())) {
    throw Error("keypoint truth: no view of frame " + std::to_string(frame) + ", camera " +
                std::to_string(camera) + ", actor " + std::to_string(actor));
  }
  return views_[(static_cast<size_t>(frame) * cameras_.size() + static_cast<size_t>(camera)) *
                    actors_.size() +
                static_cast<size_t>(actor)];
}

ActorView& KeypointTruth::at(int frame, int camera, int actor) {
  return const_cast<ActorView&>(std::as_const(*this).at(frame, camera, actor));
}

KeypointTruth read_keypoint_truth(const fs::path& dataset, KeypointLayoutId layout) {
  const std::vector<Camera> cameras =
      read_opencv_calibration(dataset / "calibration" / "opencv.yaml");
  std::vector<std::string> names;
  for (const Camera& c : cameras) names.push_back(c.name);
  std::vector<std::string> actors = read_dataset_actors(dataset);
  if (actors.empty()) actors = {"actor0"};
  const fs::path coco_file = dataset / "gt" / "keypoints_coco.json";
  Json coco;
  try {
    coco = Json::parse(read_text(coco_file));
  } catch (const Json::exception& e) {  // out_of_range too: a number beyond double's range
    throw_input_error(coco_file, 0, "", std::string("not valid JSON: ") + e.what());
  }
  KeypointTruth truth(layout, names, actors, frame_count(coco, coco_file));
  read_coco_truth(truth, coco, coco_file);
  read_joints2d_truth(truth, dataset / "gt" / "joints2d.csv");
  read_h36m_truth(truth, dataset / "gt" / "joints3d_h36m17.csv", cameras);
  return truth;
}

}  // namespace simcap
