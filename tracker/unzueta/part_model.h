// Where the tracked parts lie on the humanoid SIK solves: the centre of the head's skin, hand
// and foot meshes relative to the joint each stands for, and how far behind the surface a camera
// sees that centre lies, so that a point measured on a part becomes a target for its joint.
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
  // skin of the skull segment (the face CFOF's colour model follows; hair is another colour), a
  // hand the radiocarpal's segment, a foot the talocrural's and the toes'. The pelvis part is the
  // pelvis segment's, centred on its joint (the silhouette gives no point of the part itself).
  // Throws Error when the mesh lacks one.
  PartModel(const Skeleton& skeleton, const BodyMesh& mesh);

  int joint(Effector e) const { return joint_[index_of(e)]; }
  // The part's centre (mean of its vertices) minus its joint's centre, neutral pose, world
  // axes; in a posed body it turns with the joint's world rotation.
  const Eigen::Vector3d& centre_offset(Effector e) const { return offset_[index_of(e)]; }

  // How far the part's centre lies behind its visible surface along the unit viewing direction
  // `ray` (world), the part turned by `rotation` (its joint's world rotation). Over the whole
  // visible part: the depth, measured from the centre, of the vertices facing the camera,
  // averaged with the weight of their foreshortened area (the vertex direction from the centre
  // standing in for its normal); at the part's middle only (`middle`): the largest such depth.
  double depth_behind_surface(Effector e, const Eigen::Quaterniond& rotation,
                              const Eigen::Vector3d& ray, bool middle = false) const;

  // The joint for a part centre measured at `centre`, the part turned as in the posed body
  // (`rotation`: world joint rotations as SikBody::forward gives them).
  Eigen::Vector3d joint_from_centre(Effector e, const Eigen::Vector3d& centre,
                                    const std::vector<Eigen::Quaterniond>& rotation) const;

 private:
  std::array<int, kEffectorCount> joint_{};
  std::array<Eigen::Vector3d, kEffectorCount> offset_;
  // Per part: its vertices relative to its centre, neutral pose (at most a few hundred).
  std::array<std::vector<Eigen::Vector3d>, kEffectorCount> vertices_;
};

}  // namespace simcap::tracker
