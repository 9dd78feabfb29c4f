#include "sim/coco_keypoints.h"

#include <cmath>
#include <cstdio>

#include "core/atomic_file.h"
#include "core/error.h"
#include "models/keypoint_sets.h"

namespace simcap {
namespace {

const char* const kKeypointNames[] = {
    "nose",           "left_eye",   "right_eye",   "left_ear",   "right_ear",   "left_shoulder",
    "right_shoulder", "left_elbow", "right_elbow", "left_wrist", "right_wrist", "left_hip",
    "right_hip",      "left_knee",  "right_knee",  "left_ankle", "right_ankle"};
constexpr int kKeypoints = 17;

// Pixels to a thousandth: the JSON stays small, and 0.001 px is far below any use.
double rounded(double v) {
  return std::round(v * 1000.0) / 1000.0;
}

}  // namespace

CocoKeypoints::CocoKeypoints(const std::vector<Camera>& cameras,
                             std::vector<std::string> actor_names)
    : actors_(std::move(actor_names)) {
  for (const Camera& c : cameras) {
    cameras_.push_back(c.name);
    widths_.push_back(c.width);
    heights_.push_back(c.height);
  }
  json_["info"] = {
      {"description",
       "simcap ground truth: COCO-17 person keypoints of every actor in every camera frame"},
      {"keypoint_definitions",
       "limb keypoints are H-Anim joint centres; nose, eyes and ears are points on the head "
       "(models/keypoint_sets.h)"}};
  json_["images"] = nlohmann::ordered_json::array();
  json_["annotations"] = nlohmann::ordered_json::array();
  nlohmann::ordered_json limbs = nlohmann::ordered_json::array();
  for (const auto& [a, b] : coco17_limbs()) limbs.push_back({a + 1, b + 1});
  json_["categories"] = {{{"id", 1},
                          {"name", "person"},
                          {"supercategory", "person"},
                          {"keypoints", kKeypointNames},
                          {"skeleton", limbs}}};
}

void CocoKeypoints::add_frame(int frame,
                              const std::vector<std::vector<std::vector<JointView>>>& views,
                              const std::vector<std::vector<MaskBox>>& boxes) {
  if (views.size() != cameras_.size() || boxes.size() != cameras_.size()) {
    throw Error("COCO keypoints: frame " + std::to_string(frame) + " has views of " +
                std::to_string(views.size()) + " cameras, boxes of " +
                std::to_string(boxes.size()) + ", for " + std::to_string(cameras_.size()));
  }
  auto& images = json_["images"];
  auto& annotations = json_["annotations"];
  for (size_t c = 0; c < cameras_.size(); ++c) {
    const long image_id =
        1 + static_cast<long>(frame) * static_cast<long>(cameras_.size()) + static_cast<long>(c);
    char file[64];
    std::snprintf(file, sizeof file, "/rgb/%06d.png", frame);
    images.push_back({{"id", image_id},
                      {"file_name", cameras_[c] + file},
                      {"width", widths_[c]},
                      {"height", heights_[c]},
                      {"frame", frame},
                      {"camera", cameras_[c]}});
    for (size_t a = 0; a < actors_.size(); ++a) {
      const MaskBox& box = boxes[c].at(a);
      if (box.empty()) continue;
      const auto& kp = views[c].at(a);
      if (kp.size() != kKeypoints) throw Error("COCO keypoints: expected 17 keypoint views");
      nlohmann::ordered_json triples = nlohmann::ordered_json::array();
      nlohmann::ordered_json labels = nlohmann::ordered_json::array();
      int labelled = 0;
      for (const JointView& v : kp) {
        const int flag = v.visibility == Visibility::visible        ? 2
                         : v.visibility == Visibility::out_of_frame ? 0
                                                                    : 1;
        triples.push_back(flag ? rounded(v.pixel.x()) : 0.0);
        triples.push_back(flag ? rounded(v.pixel.y()) : 0.0);
        triples.push_back(flag);
        labelled += flag > 0;
        labels.push_back(visibility_name(v.visibility));
      }
      annotations.push_back({{"id", annotations.size() + 1},
                             {"image_id", image_id},
                             {"category_id", 1},
                             {"actor", actors_[a]},
                             {"keypoints", triples},
                             {"num_keypoints", labelled},
                             {"visibility", labels},
                             {"bbox", {box.x0, box.y0, box.x1 - box.x0 + 1, box.y1 - box.y0 + 1}},
                             {"area", box.pixels},
                             {"iscrowd", 0}});
    }
  }
}

void CocoKeypoints::write(const std::filesystem::path& path) const {
  write_text_atomic(path, json_.dump() + "\n");
}

}  // namespace simcap
