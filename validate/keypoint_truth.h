// The ground truth of a detector layout's keypoints in every image of a dataset: per frame,
// camera and actor each keypoint's true pixel and visibility, and the actor's COCO area.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "models/keypoint_layouts.h"
#include "validate/visibility.h"

namespace simcap {

struct TruthKeypoint {
  bool known = false;  // the layout's keypoint has ground truth here (LayoutKeypoint::truth)
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  // `missing` for a known pixel without a label: the Human3.6M-only points (Hip, Spine, Head),
  // projected from gt/joints3d_h36m17.csv, are labelled only out_of_frame (outside the image).
  VisibilityLabel visibility = VisibilityLabel::missing;
};

// One actor in one image.
struct ActorView {
  bool annotated = false;  // the actor has pixels in the image (an entry of keypoints_coco.json)
  double area = 0;         // its mask pixels (COCO's area, the OKS scale s^2)
  double box_height = 0;   // its mask box's height in pixels (the body height of 2D PCK)
  std::vector<TruthKeypoint> keypoints;  // the layout's order
};

class KeypointTruth {
 public:
  KeypointTruth(KeypointLayoutId layout, std::vector<std::string> cameras,
                std::vector<std::string> actors, int frames);

  KeypointLayoutId layout() const { return layout_; }
  const std::vector<std::string>& cameras() const { return cameras_; }
  const std::vector<std::string>& actors() const { return actors_; }
  int frames() const { return frames_; }
  const ActorView& at(int frame, int camera, int actor) const;
  ActorView& at(int frame, int camera, int actor);

 private:
  KeypointLayoutId layout_;
  std::vector<std::string> cameras_, actors_;
  int frames_;
  std::vector<ActorView> views_;  // [(frame * cameras + camera) * actors + actor]
};

// Reads DATASET's calibration/opencv.yaml, scene.yaml (actors), gt/keypoints_coco.json (images,
// areas, COCO points), gt/joints2d.csv (H-Anim joints) and, when the layout has Human3.6M-only
// points, gt/joints3d_h36m17.csv. Frames are 0 .. the last frame of keypoints_coco.json. A
// keypoint_coco.json written before it had `visibility` labels its occluded face points
// `missing`. Errors name the file and field.
KeypointTruth read_keypoint_truth(const std::filesystem::path& dataset, KeypointLayoutId layout);

}  // namespace simcap
