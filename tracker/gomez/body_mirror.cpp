// Reflected and turned body states (body_mirror.h).
#include "tracker/gomez/body_mirror.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/pose.h"

namespace simcap::tracker::gomez {

BodyMirror::BodyMirror(const BodyDofs& dofs) : dofs_(&dofs) {
  const int n = dofs.size();
  partner_.resize(n);
  sign_.resize(n);
  for (int i = 0; i < n; ++i) {
    const Dof& d = dofs[i];
    partner_[i] = i;
    if (d.name.starts_with("l_") || d.name.starts_with("r_")) {
      const std::string other = (d.name[0] == 'l' ? "r" : "l") + d.name.substr(1);
      partner_[i] = dofs.find(other);
      if (partner_[i] < 0) throw Error("monocular body: no mirror DOF '" + other + "'");
    }
    sign_[i] = d.translation || d.axis == 0 ? 1.0 : -1.0;
  }
  if (dofs.kind() == BodyKind::full) turn_ = dofs.require("root_turn");
}

State BodyMirror::reflect(const State& x, const Eigen::Vector3d& camera_centre) const {
  if (!available()) return x;
  const BodyDofs& dofs = *dofs_;
  State y(x.size());
  for (int i = 0; i < dofs.size(); ++i) y[i] = sign_[i] * x[partner_[i]];
  // The reflection S_n through the plane of horizontal normal n, applied after the reflection M
  // across the body's own sagittal plane (x -> -x in the neutral frame): S_n M is the turn
  // R_y(phi), and the root's rotation R_y(t) R_x R_z becomes R_y(phi) M R_y(t) R_x R_z M =
  // R_y(phi - t) R_x R_z(-roll). With n = (nx, 0, nz): phi = atan2(-2 nx nz, 2 nx^2 - 1).
  const Eigen::Vector3d root = joint_positions(dofs.skeleton(), dofs.pose(x))[0];
  Eigen::Vector3d n = root - camera_centre;
  n.y() = 0;
  if (n.norm() < 1e-9) return x;
  n.normalize();
  const double phi = std::atan2(-2 * n.x() * n.z(), 2 * n.x() * n.x() - 1);
  // The new heading nearest the old one's representation (the box spans two turns either way).
  y[turn_] = x[turn_] + std::remainder(phi - 2 * x[turn_], 2 * std::numbers::pi);
  return dofs.clamp(y);
}

}  // namespace simcap::tracker::gomez
