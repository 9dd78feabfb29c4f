// Segment masses and centres of mass of the simcap humanoid (Dempster's cadaver data as tabulated
// by Winter), and from them the whole-body centre of mass of a pose, for balance.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "models/skeleton.h"

namespace simcap {

// D. A. Winter, "Biomechanics and Motor Control of Human Movement", 4th ed. (2009), Table 4.1:
// each segment's fraction of the body mass and the position of its centre of mass between its
// proximal and distal ends. The ends are joints of build_humanoid (H-Anim names); where a
// landmark has no joint of its own simcap takes the nearest (hip centre for the greater
// trochanter, vl1 for T12-L1, vl5 for L4-L5, skullbase for the ear canal, the knuckles 45% of
// the way from the wrist to the hand tip).
class BodyMass {
 public:
  // Throws Error when the skeleton lacks one of the joints above.
  explicit BodyMass(const Skeleton& skeleton);

  // The whole-body centre of mass for the world joint positions `joints` (joint_positions() of a
  // pose of the skeleton).
  Eigen::Vector3d center(const std::vector<Eigen::Vector3d>& joints) const;

 private:
  struct Segment {
    int proximal, distal;  // joints; distal -1: the mid-point of the two hips (pelvis)
    double distal_scale;   // the distal landmark lies this far along proximal -> distal joint
    double mass, com;      // fraction of body mass; centre's fraction of the way from proximal
  };
  std::vector<Segment> segments_;
  int hips_[2] = {-1, -1};
};

}  // namespace simcap
