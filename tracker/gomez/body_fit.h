// Sizing the monocular tracker's skeleton and finding its pose from 3D joint positions (the
// ground truth of the first frame for --init gt): bone lengths are measured, angles fitted.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "models/skeleton.h"
#include "tracker/gomez/body_dofs.h"

namespace simcap::tracker::gomez {

struct NamedPoint {
  std::string joint;  // H-Anim name
  Eigen::Vector3d position;
};

// build_humanoid's skeleton with each bone as long as between the given joints (bones whose two
// ends are not both given, or shorter than 1 cm in the humanoid, keep the humanoid's proportions
// at the height that the measured bones suggest: their median length ratio times 1.75 m).
// Throws Error when no bone can be measured.
Skeleton sized_humanoid(const std::vector<NamedPoint>& joints);

// The state of `dofs` whose joints come closest (least squares) to the given positions, found by
// damped Gauss-Newton inside the box from `start`. Joints the skeleton lacks are ignored.
State fit_joints(const BodyDofs& dofs, const std::vector<NamedPoint>& joints, const State& start,
                 int iterations = 60);

// A start for fit_joints: root at the given humanoid_root, heading from the hips (l_hip to
// r_hip is the body's -X), every angle zero (clamped to the box).
State start_from_joints(const BodyDofs& dofs, const std::vector<NamedPoint>& joints);

}  // namespace simcap::tracker::gomez
