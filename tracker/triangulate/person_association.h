// Which detected person in each camera is the tracked actor: the one nearest the pose predicted
// from the last frame, or, with no prediction, the views that triangulate consistently.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "core/camera.h"

namespace simcap::tracker {

// One person found by a 2D detector in one image: x, y, score per keypoint of the layout
// (score 0: not found).
struct PersonKeypoints {
  std::vector<Eigen::Vector3d> keypoints;
};

struct AssociationOptions {
  double min_confidence = 0.2;  // keypoints scored lower are ignored
  // A person is the predicted one when its median keypoint distance to the prediction's
  // projection is below this fraction of the projected body's bounding-box diagonal.
  double gate = 0.25;
  // Seeding: a view joins the reference when its keypoints triangulate with the reference's to
  // a median reprojection error below this (pixels).
  double seed_error_px = 20.0;
};

struct Association {
  std::vector<int> person;   // per camera: index into that camera's people, -1 none
  std::vector<double> cost;  // per camera: the chosen person's median distance/error, pixels
  bool seeded = false;       // chosen without a prediction
};

// `predicted`: the keypoints' world positions expected in this frame (nullopt: unknown), or
// empty to seed. With a prediction, fewer than two cameras matching it falls back to seeding.
// Seeding takes as reference the most prominent person (summed confident scores times the
// keypoints' bounding-box diagonal) and adds in every other camera the person that
// triangulates with it best.
Association associate_people(std::span<const Camera> cameras,
                             const std::vector<std::vector<PersonKeypoints>>& people,
                             const std::vector<std::optional<Eigen::Vector3d>>& predicted,
                             const AssociationOptions& options = {});

}  // namespace simcap::tracker
