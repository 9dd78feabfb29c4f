// The monocular tracker's body surface: one tapered capsule per segment (two side by side for the
// trunk), attached to the joints of its skeleton, each cut along its axis into colour cells
// whose colour class is learned on the first frame (a short sleeve, hair on top of the head).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "models/skeleton.h"
#include "tracker/gomez/body_dofs.h"

namespace simcap::tracker::gomez {

// Colour cells per capsule, from its start (a) to its end (b).
inline constexpr int kCellsPerCapsule = 6;

struct Capsule {
  int joint = 0;      // skeleton joint whose frame carries it
  Eigen::Vector3d a;  // ends in the joint's frame (its neutral-pose world frame moved to the
  Eigen::Vector3d b;  // joint's centre), metres
  double ra = 0;      // radius at a, metres
  double rb = 0;      // radius at b
  Part part = Part::torso;
  int mirror = -1;  // the same capsule on the other side, -1 on the midline
  // The head's face direction in the joint's frame (zero: none). The surface facing away from
  // it draws the last cell, the crown's, at every height: from behind a head shows its hair,
  // from the front its face under the hairline -- the cue that tells a body facing the camera
  // from one turned away, whose outlines match.
  Eigen::Vector3d front = Eigen::Vector3d::Zero();
};

struct BodyShape {
  std::vector<Capsule> capsules;
  int cell_count() const { return static_cast<int>(capsules.size()) * kCellsPerCapsule; }
};

// Scales of the average adult's capsules for one person (the thesis's shape adjustment, §3.3).
struct ShapeScales {
  double trunk_width = 1;  // the trunk's two capsules' spacing
  double trunk_girth = 1;  // trunk, shoulder line and pelvis radii
  double head = 1;         // head and neck radii
  double arms = 1;         // upper arm, forearm and hand radii
  double legs = 1;         // thigh and calf radii (the feet keep theirs: they stand on them)
};

// Capsules for `kind` around `skeleton` (build_humanoid's names), sized by its standing height
// (head top to floor in the neutral pose). Radii are round fractions of the height for a
// clothed average adult (simcap's choice, near ANSUR II breadths / stature), times `scales`.
BodyShape make_body_shape(const Skeleton& skeleton, BodyKind kind, const ShapeScales& scales = {});

// The soles of the feet (the bottoms of the foot capsules' ends), for BodyDofs' floor; none
// for the upper body.
std::vector<FloorContact> sole_points(const BodyShape& shape, const Skeleton& skeleton);

// The skeleton's standing height: its skull_tip above the lowest joint, plus the ankle height.
double standing_height(const Skeleton& skeleton);

}  // namespace simcap::tracker::gomez
