// SIK's collision geometry (Unzueta 2009 §4.6), measured on a neutral body mesh: torso prisms
// per spine segment, elbow and wrist spheres, the feet's extreme vertices, the floor plane.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "models/body_mesh.h"
#include "tracker/unzueta/sik_body.h"

namespace simcap {

// A torso prism in the frame of spine joint `joint`: it runs along `axis` (the neutral vector to
// the next spine joint); its cross-section in the joint's XZ plane is x in [-half_width,
// half_width], z in [-back, front], measured from the spine axis.
struct SikTorsoPrism {
  int joint = -1;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitY();
  double half_width = 0.0, front = 0.0, back = 0.0;
};

// How deep a sphere lies inside the torso: p_e (its deepest point) and p_t (the prism's outer
// point) along the ray from the prism's centre line through the sphere's centre, in the plane of
// the prism's cross-section (thesis Fig. 41). depth = |p_t - p_e|, 0 when clear.
struct SikPenetration {
  double depth = 0.0;
  Eigen::Vector3d deepest = Eigen::Vector3d::Zero();  // p_e, world
  Eigen::Vector3d outer = Eigen::Vector3d::Zero();    // p_t, world
};

class SikCollider {
 public:
  // Measures the prisms, sphere radii and foot points on `mesh` (built around body.skeleton()).
  SikCollider(const SikBody& body, const BodyMesh& mesh, double floor_y = 0.0);

  double elbow_radius(int side) const { return elbow_radius_[side]; }
  double wrist_radius(int side) const { return wrist_radius_[side]; }
  double floor_y() const { return floor_y_; }

  // The deepest penetration of the sphere (centre, radius) into any torso prism, for the body's
  // world joint rotations and positions.
  SikPenetration torso(const std::vector<Eigen::Quaterniond>& rotation,
                       const std::vector<Eigen::Vector3d>& position, const Eigen::Vector3d& centre,
                       double radius) const;
  // The lowest point of a foot (world) whose ankle has this world rotation and position.
  Eigen::Vector3d lowest_foot_point(int side, const Eigen::Quaterniond& ankle_rotation,
                                    const Eigen::Vector3d& ankle_position) const;

 private:
  std::vector<SikTorsoPrism> prisms_;
  std::array<double, 2> elbow_radius_{}, wrist_radius_{};
  std::array<std::vector<Eigen::Vector3d>, 2> foot_;  // ankle-relative, neutral frame
  double floor_y_ = 0.0;
};

}  // namespace simcap
