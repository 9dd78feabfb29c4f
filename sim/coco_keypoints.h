// COCO person-keypoint annotations of a dataset (gt/keypoints_coco.json): one image entry per
// camera frame, one annotation per actor seen in it, with the ground truth's COCO-17 keypoints,
// visibility flags and the actor's mask box, readable by pycocotools and COCO-format trainers.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/camera.h"
#include "sim/ground_truth.h"
#include "sim/mask_boxes.h"

namespace simcap {

class CocoKeypoints {
 public:
  CocoKeypoints(const std::vector<Camera>& cameras, std::vector<std::string> actor_names);

  // Image ids are 1 + frame * cameras + camera; file_name is "<camera>/rgb/%06d.png" (relative
  // to the dataset). Per actor whose mask box in that image is not empty: keypoints as
  // x, y, v triples in COCO-17 order, pixel coordinates as simcap's (the centre of the top-left
  // pixel is (0, 0), as COCO's keypoint annotations), v = 2 visible, 1 self_occluded or
  // scene_occluded, 0 out_of_frame (then x = y = 0); num_keypoints counts v > 0; bbox
  // [x, y, width, height] covers the actor's mask pixels (x, y at their top-left edges), area
  // their count; iscrowd 0; and simcap's own member visibility: per keypoint the ground
  // truth's label (visible, self_occluded, scene_occluded, out_of_frame), which v merges. `views`
  // are FrameTruth::coco_views, `boxes` [camera][actor].
  void add_frame(int frame, const std::vector<std::vector<std::vector<JointView>>>& views,
                 const std::vector<std::vector<MaskBox>>& boxes);
  // images, annotations (in frame, camera, actor order) and categories (person, with COCO's
  // keypoint names and limbs).
  const nlohmann::ordered_json& json() const { return json_; }
  void write(const std::filesystem::path& path) const;

 private:
  std::vector<std::string> cameras_;
  std::vector<int> widths_, heights_;
  std::vector<std::string> actors_;
  nlohmann::ordered_json json_;
};

}  // namespace simcap
