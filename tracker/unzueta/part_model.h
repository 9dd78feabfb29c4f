// Where the tracked parts lie on the humanoid SIK solves: the centre and thickness of the head,
// hand and foot meshes relative to the joint each stands for, so that a point measured on a
// part's surface or at its centre becomes a target for that joint.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "models/body_mesh.h"
#include "models/skeleton.h"
#include "tracker/unzueta/effectors.h"

namespace simcap::tracker {

class PartModel {
 public:
  // Reads the parts off `mesh` (built around `skeleton` in its neutral pose): the head is the
  // skull segment, a hand the radiocarpal's segment, a foot the talocrural's and the toes'. The
  // pelvis part is its joint itself (the silhouette gives no surface point of it) with the
  // torso's half-depth as thickness.
  PartModel(const Skeleton& skeleton, const BodyMesh& mesh);

  int joint(Effector e) const { return joint_[index_of(e)]; }
  // The part's centre (mean of its vertices) minus its joint's centre, neutral pose, world
  // axes; in a posed body it turns with the joint's world rotation.
  const Eigen::Vector3d& centre_offset(Effector e) const { return offset_[index_of(e)]; }
  // Distance from the part's surface to its centre, seen from outside: sqrt(2 * the smallest
  // principal variance of its vertices) (the radius of a cylinder whose surface it is).
  double radius(Effector e) const { return radius_[index_of(e)]; }

  // The part's centre for a posed body (`rotation`, `position`: world joint frames as
  // SikBody::forward gives them).
  Eigen::Vector3d centre(Effector e, const std::vector<Eigen::Quaterniond>& rotation,
                         const std::vector<Eigen::Vector3d>& position) const;
  // The joint for a part centre measured at `centre`, the part turned as in the posed body.
  Eigen::Vector3d joint_from_centre(Effector e, const Eigen::Vector3d& centre,
                                    const std::vector<Eigen::Quaterniond>& rotation) const;

 private:
  std::array<int, kEffectorCount> joint_{};
  std::array<Eigen::Vector3d, kEffectorCount> offset_;
  std::array<double, kEffectorCount> radius_{};
};

}  // namespace simcap::tracker
