// One keypoint of one person as a 2D detector saw it in one camera: the triangulator's input,
// independent of the file format and keypoint layout the detections came in.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace simcap::tracker {

struct KeypointObservation {
  int camera = 0;  // index into the dataset's cameras
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double confidence = 1.0;  // the detector's score, 0..1
};

// Every camera's observation of one keypoint in one frame.
using KeypointViews = std::vector<KeypointObservation>;

}  // namespace simcap::tracker
