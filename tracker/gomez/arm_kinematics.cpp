// Analytic arm inverse kinematics, swivel angle and kinematic flips (arm_kinematics.h).
#include "tracker/gomez/arm_kinematics.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/pose.h"

namespace simcap::tracker::gomez {
namespace {

// Rotation frame of a vector pair: first axis along u, second towards v.
Eigen::Matrix3d pair_frame(const Eigen::Vector3d& u, const Eigen::Vector3d& v) {
  const Eigen::Vector3d e1 = u.normalized();
  Eigen::Vector3d e2 = v - v.dot(e1) * e1;
  if (e2.norm() < 1e-12) e2 = e1.unitOrthogonal();
  e2.normalize();
  Eigen::Matrix3d m;
  m << e1, e2, e1.cross(e2);
  return m;
}

// Distances t along the unit ray o + t d where it meets the sphere (centre, radius).
std::vector<double> ray_sphere(const Eigen::Vector3d& o, const Eigen::Vector3d& d,
                               const Eigen::Vector3d& centre, double radius) {
  const Eigen::Vector3d oc = centre - o;
  const double b = d.dot(oc);
  const double disc = b * b - (oc.squaredNorm() - radius * radius);
  if (disc < 0) return {};
  const double r = std::sqrt(disc);
  return {b - r, b + r};
}

}  // namespace

ArmKinematics::ArmKinematics(const BodyDofs& dofs, Limbs limbs) : dofs_(&dofs) {
  const Skeleton& s = dofs.skeleton();
  const bool arms = limbs == Limbs::arms;
  for (int side = 0; side < 2; ++side) {
    const std::string p = side == 0 ? "l_" : "r_";
    shoulder_[side] = s.require(p + (arms ? "shoulder" : "hip"));
    elbow_[side] = s.require(p + (arms ? "elbow" : "knee"));
    wrist_[side] = s.require(p + (arms ? "radiocarpal" : "talocrural"));
    if (dofs.joint_dofs(shoulder_[side]).size() != 3 || dofs.joint_dofs(elbow_[side]).size() != 1 ||
        dofs[dofs.joint_dofs(elbow_[side])[0]].axis != 0) {
      throw Error("limb kinematics: the " + p + (arms ? "arm" : "leg") +
                  " needs 3 DOFs at its root joint and a hinge about X");
    }
    elbow_dof_[side] = dofs.joint_dofs(elbow_[side])[0];
    upper_[side] = s.offset(elbow_[side]);
    fore_[side] = s.offset(wrist_[side]);
  }
}

ArmPoints ArmKinematics::points(const State& x, int side) const {
  const auto g = forward_kinematics(dofs_->skeleton(), dofs_->pose(x));
  return {g[shoulder_[side]].translation(), g[elbow_[side]].translation(),
          g[wrist_[side]].translation(), g[dofs_->skeleton()[shoulder_[side]].parent].linear()};
}

bool ArmKinematics::solve(State& x, int side, const Eigen::Vector3d& elbow,
                          const Eigen::Vector3d& wrist) const {
  return solve_end(x, side, elbow, wrist, fore_[side]);
}

bool ArmKinematics::solve_end(State& x, int side, const Eigen::Vector3d& elbow,
                              const Eigen::Vector3d& end, const Eigen::Vector3d& f0) const {
  const ArmPoints arm = points(x, side);
  const Eigen::Vector3d e = arm.parent.transpose() * (elbow - arm.shoulder);
  const Eigen::Vector3d w = arm.parent.transpose() * (end - arm.shoulder);
  const Eigen::Vector3d& u0 = upper_[side];
  // |u0 + Rx(t) f0|^2 = |w|^2 with u0 . Rx(t) f0 = A + B cos t + C sin t.
  const double A = u0.x() * f0.x();
  const double B = u0.y() * f0.y() + u0.z() * f0.z();
  const double C = u0.z() * f0.y() - u0.y() * f0.z();
  const double K = 0.5 * (w.squaredNorm() - u0.squaredNorm() - f0.squaredNorm()) - A;
  const double R = std::hypot(B, C);
  bool reachable = R > 1e-12 && std::abs(K) <= R * (1 + 1e-9);
  const double phi = std::atan2(C, B),
               spread = std::acos(std::clamp(K / std::max(R, 1e-12), -1.0, 1.0));
  const Dof& ed = (*dofs_)[elbow_dof_[side]];
  double angle = x[elbow_dof_[side]];
  double best = INFINITY;
  for (const double t : {phi + spread, phi - spread}) {
    const double a = std::remainder(t, 2 * std::numbers::pi);
    const double outside = std::max(0.0, ed.lower - a) + std::max(0.0, a - ed.upper);
    const double cost = 1e3 * outside + std::abs(a - x[elbow_dof_[side]]);
    if (cost < best) {
      best = cost;
      angle = a;
    }
  }
  x[elbow_dof_[side]] = angle;
  const Eigen::Vector3d v0 =
      u0 + Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix() * f0;
  const Eigen::Matrix3d Rs = pair_frame(e, w) * pair_frame(u0, v0).transpose();
  dofs_->set_joint(shoulder_[side], Eigen::Quaterniond(Rs), x);
  bool inside = true;
  for (const int i : dofs_->joint_dofs(shoulder_[side])) {
    const Dof& d = (*dofs_)[i];
    inside = inside && x[i] >= d.lower - 1e-9 && x[i] <= d.upper + 1e-9;
  }
  inside = inside && angle >= ed.lower - 1e-9 && angle <= ed.upper + 1e-9;
  if (!inside || !reachable) {
    for (const int i : dofs_->joint_dofs(shoulder_[side])) {
      x[i] = std::clamp(x[i], (*dofs_)[i].lower, (*dofs_)[i].upper);
    }
    x[elbow_dof_[side]] = std::clamp(angle, ed.lower, ed.upper);
  }
  return inside && reachable;
}

namespace {

// The swivel circle of an arm reaching `wrist`: centre, radius and two unit axes in its plane.
struct Circle {
  Eigen::Vector3d centre, r1, r2;
  double radius = 0;
};

std::optional<Circle> swivel_circle(const ArmPoints& arm, const Eigen::Vector3d& wrist, double L1,
                                    double L2) {
  const Eigen::Vector3d sw = wrist - arm.shoulder;
  const double d = sw.norm();
  if (d < 1e-9 || d > L1 + L2 || d < std::abs(L1 - L2)) return std::nullopt;
  const Eigen::Vector3d n = sw / d;
  const double a = (L1 * L1 - L2 * L2 + d * d) / (2 * d);
  Circle c;
  c.centre = arm.shoulder + a * n;
  c.radius = std::sqrt(std::max(0.0, L1 * L1 - a * a));
  Eigen::Vector3d ref = arm.parent * Eigen::Vector3d(0, -1, 0);
  ref -= ref.dot(n) * n;
  if (ref.norm() < 1e-6) {
    ref = arm.parent * Eigen::Vector3d(0, 0, -1);
    ref -= ref.dot(n) * n;
  }
  c.r1 = ref.normalized();
  c.r2 = n.cross(c.r1);
  return c;
}

}  // namespace

std::optional<Eigen::Vector3d> ArmKinematics::swivel_elbow(const ArmPoints& arm,
                                                           const Eigen::Vector3d& wrist,
                                                           double swivel) const {
  return swivel_elbow(arm, wrist, swivel, (arm.wrist - arm.elbow).norm());
}

std::optional<Eigen::Vector3d> ArmKinematics::swivel_elbow(const ArmPoints& arm,
                                                           const Eigen::Vector3d& end,
                                                           double swivel, double L2) const {
  const double L1 = (arm.elbow - arm.shoulder).norm();
  const auto c = swivel_circle(arm, end, L1, L2);
  if (!c) return std::nullopt;
  return c->centre + c->radius * (std::cos(swivel) * c->r1 + std::sin(swivel) * c->r2);
}

double ArmKinematics::swivel(const ArmPoints& arm) const {
  const double L1 = (arm.elbow - arm.shoulder).norm(), L2 = (arm.wrist - arm.elbow).norm();
  const auto c = swivel_circle(arm, arm.wrist, L1, L2);
  if (!c) return 0.0;
  const Eigen::Vector3d e = arm.elbow - c->centre;
  return std::atan2(e.dot(c->r2), e.dot(c->r1));
}

std::vector<State> ArmKinematics::flips(const State& x,
                                        const Eigen::Vector3d& camera_centre) const {
  // Per arm, the (elbow, wrist) pairs on the same camera rays: the original first.
  std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>> options[2];
  for (int side = 0; side < 2; ++side) {
    const ArmPoints arm = points(x, side);
    const double L1 = (arm.elbow - arm.shoulder).norm(), L2 = (arm.wrist - arm.elbow).norm();
    const Eigen::Vector3d de = (arm.elbow - camera_centre).normalized();
    const Eigen::Vector3d dw = (arm.wrist - camera_centre).normalized();
    const double te = (arm.elbow - camera_centre).norm(), tw = (arm.wrist - camera_centre).norm();
    options[side].push_back({arm.elbow, arm.wrist});
    std::vector<Eigen::Vector3d> elbows = {arm.elbow};
    for (const double t : ray_sphere(camera_centre, de, arm.shoulder, L1)) {
      if (std::abs(t - te) > 1e-6 && t > 0) elbows.push_back(camera_centre + t * de);
    }
    for (size_t k = 0; k < elbows.size(); ++k) {
      for (const double t : ray_sphere(camera_centre, dw, elbows[k], L2)) {
        if (t <= 0 || (k == 0 && std::abs(t - tw) <= 1e-6)) continue;
        options[side].push_back({elbows[k], camera_centre + t * dw});
      }
    }
  }
  std::vector<State> out;
  for (size_t a = 0; a < options[0].size(); ++a) {
    for (size_t b = 0; b < options[1].size(); ++b) {
      if (a == 0 && b == 0) continue;
      State y = x;
      const bool left = a == 0 || solve(y, 0, options[0][a].first, options[0][a].second);
      const bool right = b == 0 || solve(y, 1, options[1][b].first, options[1][b].second);
      if (left && right) out.push_back(std::move(y));
    }
  }
  return out;
}

std::optional<State> ArmKinematics::reach_point(const State& x, int side,
                                                const Eigen::Vector3d& hand,
                                                const Eigen::Vector3d& target) const {
  const ArmPoints arm = points(x, side);
  // The hand point is a fixed offset in the elbow's frame (the wrist's angles stay): the arm's
  // IK solved for it as the end of a longer forearm puts it on the target exactly.
  const Eigen::Vector3d end =
      fore_[side] + dofs_->pose(x).rotations[wrist_[side]].toRotationMatrix() * hand;
  const double L2 = end.norm(), present = swivel(arm);
  // The swivel nearest the present one that the limits allow (the shoulder's twist limits most
  // of the circle out).
  for (int turn = 0; turn < 15; ++turn) {
    const double sw = present + (turn % 2 == 0 ? 1 : -1) * 0.4 * ((turn + 1) / 2);
    State y = x;
    const auto elbow = swivel_elbow(arm, target, sw, L2);
    if (elbow && solve_end(y, side, *elbow, target, end)) return y;
  }
  return std::nullopt;
}

std::vector<State> ArmKinematics::reach_ray(const State& x, int side, const Eigen::Vector3d& hand,
                                            const Eigen::Vector3d& origin,
                                            const Eigen::Vector3d& direction, int depths) const {
  std::vector<State> out;
  const ArmPoints arm = points(x, side);
  const Eigen::Vector3d end =
      fore_[side] + dofs_->pose(x).rotations[wrist_[side]].toRotationMatrix() * hand;
  const double L1 = upper_[side].norm(), L2 = end.norm();
  // The stretch of the ray within reach, shrunk a little so that its ends stay reachable with the
  // elbow not quite straight.
  const std::vector<double> ts = ray_sphere(origin, direction, arm.shoulder, 0.98 * (L1 + L2));
  if (ts.empty() || ts[1] <= 0 || depths <= 0) return out;
  const double t0 = std::max(ts[0], 0.0), t1 = ts[1];
  // The limits allow only part of the stretch (a hand far behind the shoulder is out of them): it
  // is sampled four times as densely as asked, and as many of the allowed depths as asked are
  // kept, spread over them.
  std::vector<State> allowed;
  const int samples = 4 * depths;
  for (int k = 0; k < samples; ++k) {
    const Eigen::Vector3d target = origin + (t0 + (k + 0.5) / samples * (t1 - t0)) * direction;
    if (auto y = reach_point(x, side, hand, target)) allowed.push_back(std::move(*y));
  }
  const int n = static_cast<int>(allowed.size());
  for (int k = 0; k < std::min(n, depths); ++k) {
    out.push_back(std::move(allowed[n <= depths ? k : (2 * k + 1) * n / (2 * depths)]));
  }
  return out;
}

}  // namespace simcap::tracker::gomez
