#include "scenes/scene.h"

namespace simcap {

Eigen::Isometry3d actor_placement(const Actor& actor) {
  Eigen::Isometry3d placement = Eigen::Isometry3d::Identity();
  placement.translate(actor.offset);
  placement.rotate(Eigen::AngleAxisd(actor.yaw_rad, Eigen::Vector3d::UnitY()));
  return placement;
}

}  // namespace simcap
