// Which detected person in each camera is the tracked actor: the one nearest where the actor was
// expected in that image, else the one that triangulates consistently with the cameras that know.
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
  // A person is the expected one when its median keypoint distance to the expectation is below
  // this fraction of the expectation's bounding-box diagonal.
  double gate = 0.25;
  // With a single camera chosen, a second joins when its person's keypoints triangulate with
  // the chosen one's to a median reprojection error below this (pixels).
  double join_error_px = 20.0;
};

// How a camera's person was chosen.
enum class AssociationKind { none, tracked, joined, seeded };

struct Association {
  std::vector<int> person;   // per camera: index into that camera's people, -1 none
  std::vector<double> cost;  // per camera: median distance to the expectation / pair error, px
  std::vector<AssociationKind> kind;
};

// `expected[c]`: where the actor's keypoints are expected in camera c (the person chosen there in
// the last frame, or the first frame's ground truth projected); no keypoints: nothing expected.
// Cameras whose expectation a person matches keep it ("tracked"); the others take the person
// nearest the tracked people's keypoints triangulated and projected ("joined"; with a single
// tracked camera, the view that triangulates best with it joins first). Without any tracked
// camera the most prominent person of all (summed confident scores times the keypoints'
// bounding-box diagonal) is the reference ("seeded") and the other cameras join it.
Association associate_people(std::span<const Camera> cameras,
                             const std::vector<std::vector<PersonKeypoints>>& people,
                             const std::vector<PersonKeypoints>& expected,
                             const AssociationOptions& options = {});

}  // namespace simcap::tracker
