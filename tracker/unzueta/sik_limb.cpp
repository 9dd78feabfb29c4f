#include "tracker/unzueta/sik_limb.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace simcap {
namespace {

// Collision responses iterate until the part is out (thesis §4.6: "until the elbow exits the
// torso"), at most this often; each step is a lower bound of the turn needed, so the depth
// shrinks geometrically, and a micrometre counts as out.
constexpr int kMaxCollisionIterations = 50;
constexpr double kClear = 1e-6;
// §4.6.1, bent arm: the upper arm swivels k * depth / |upper arm| radians per iteration, k = 1.
constexpr double kSwivelGain = 1.0;
// A foot this little below the floor counts as on it (the lift converges geometrically).
constexpr double kFloorTolerance = 1e-4;
constexpr double kTiny = 1e-9;
// A swivel toward a middle target that leaves the limits is cut to within 2^-30 of their edge.
constexpr int kSwivelBisections = 30;
// TGBSIK's swivel: a 5-degree grid over the whole turn, then 30 golden-section steps.
constexpr int kSwivelSamples = 72;
constexpr int kSwivelRefinements = 30;

double wrap(double a) {
  return std::remainder(a, 2 * std::numbers::pi);
}

// Signed angle from a to b about unit axis n, both taken in the plane normal to n.
double angle_about(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& n) {
  const Eigen::Vector3d pa = a - a.dot(n) * n, pb = b - b.dot(n) * n;
  return std::atan2(pa.cross(pb).dot(n), pa.dot(pb));
}

}  // namespace

SikLimbSolver::SikLimbSolver(const SikBody& body, const SikLimits& limits,
                             const SikCollider* collider, SikSwivel swivel)
    : body_(body), limits_(limits), collider_(collider), swivel_(swivel) {
  for (int side : {kLeft, kRight}) {
    arm_[side] = geometry(body.arm(side));
    leg_[side] = geometry(body.leg(side));
  }
}

SikLimbSolver::Geometry SikLimbSolver::geometry(const SikLimb& limb) const {
  Geometry g;
  g.ab = body_.offset(limb.b);
  g.bc = body_.offset(limb.c);
  g.hinge = limb.hinge_axis;
  g.swivel = limb.swivel_axis;
  g.length_ab = g.ab.norm();
  g.length_bc = g.bc.norm();
  const Eigen::Vector3d& h = g.hinge;
  const Eigen::Vector3d ab_perp = g.ab - g.ab.dot(h) * h, bc_perp = g.bc - g.bc.dot(h) * h;
  g.c0 = g.ab.squaredNorm() + g.bc.squaredNorm() + 2 * g.ab.dot(h) * g.bc.dot(h);
  g.m = ab_perp.norm() * bc_perp.norm();
  g.delta = angle_about(ab_perp, bc_perp, h);
  return g;
}

void SikLimbSolver::update(const SikLimb& limb, const Pose& pose, SikWorld& world) const {
  for (int j : {limb.a, limb.b, limb.c}) {
    const int p = body_.parent(j);
    world.rotation[j] = world.rotation[p] * pose.rotations[j];
    world.position[j] = world.position[p] + world.rotation[p] * body_.offset(j);
  }
}

void SikLimbSolver::turn(int j, const Eigen::Quaterniond& world_turn, Pose& pose,
                         const SikWorld& world) const {
  const Eigen::Quaterniond& parent = world.rotation[body_.parent(j)];
  pose.rotations[j] = (parent.conjugate() * world_turn * parent * pose.rotations[j]).normalized();
}

double SikLimbSolver::flexion_for_reach(const SikLimb& limb, const Geometry& g, double reach,
                                        bool limits) const {
  // Law of cosines on the bent limb (Alg. 13 line 4): |AC|^2 = c0 + 2 m cos(phi + delta).
  const double c = g.m > kTiny ? std::clamp((reach * reach - g.c0) / (2 * g.m), -1.0, 1.0) : 1.0;
  const double phi = std::acos(c) - g.delta;
  if (!limits) return phi;
  const SikJointLimit& l = limits_[limb.b];
  return std::clamp(phi, l.min, l.max);
}

Eigen::Quaterniond SikLimbSolver::aim(const Geometry& g, double flexion,
                                      const Eigen::Vector3d& direction) const {
  // Alg. 13 lines 2-4: the shortest turn of the stretched limb onto the target line, then a turn
  // about B's anatomical flexion axis by psi2, the angle at A of the triangle with sides |AB|,
  // |BC| and the reach the flexion gives (law of cosines). B ends behind the line for an elbow
  // and in front of it for a knee, at |BC| from the limb's end on the line.
  const double reach = (g.ab + Eigen::AngleAxisd(flexion, g.hinge) * g.bc).norm();
  const double psi2 =
      std::acos(std::clamp((g.length_ab * g.length_ab + reach * reach - g.length_bc * g.length_bc) /
                               std::max(2 * g.length_ab * reach, kTiny),
                           -1.0, 1.0));
  const Eigen::Vector3d line = direction.normalized();
  const Eigen::Quaterniond onto = Eigen::Quaterniond::FromTwoVectors(g.ab + g.bc, line);
  Eigen::Vector3d axis = onto * g.swivel;
  axis -= axis.dot(line) * line;
  if (axis.norm() < kTiny) axis = line.unitOrthogonal();
  const Eigen::Vector3d upper = Eigen::AngleAxisd(-psi2, axis.normalized()) * line;
  return (Eigen::Quaterniond::FromTwoVectors(onto * g.ab, upper) * onto).normalized();
}

void SikLimbSolver::bend_toward(const SikLimb& limb, const Geometry& g,
                                const Eigen::Vector3d& target, bool limits, Pose& pose,
                                SikWorld& world) const {
  const Eigen::Vector3d& h = g.hinge;
  const Eigen::Vector3d u = g.ab / g.length_ab;
  auto to_b = [&] {  // target from B, in A's (= B's unflexed) frame
    return Eigen::Vector3d(world.rotation[limb.a].conjugate() * (target - world.position[limb.b]));
  };
  const SikJointLimit& hinge_limit = limits_[limb.b];
  auto flexion_outside = [&](double phi) {
    if (!limits || (phi >= hinge_limit.min && phi <= hinge_limit.max)) return 0.0;
    return std::min(std::abs(wrap(phi - hinge_limit.min)), std::abs(wrap(phi - hinge_limit.max)));
  };

  // Lines 8-10: turn A about its bone until B's flexion axis is normal to BD, choosing of the two
  // solutions the one whose flexion lies in range, then the smaller turn.
  const Eigen::Vector3d bd = to_b();
  const Eigen::Vector3d h_perp = h - h.dot(u) * u, bd_perp = bd - bd.dot(u) * u;
  if (h_perp.norm() > kTiny && bd_perp.norm() > 1e-6 * bd.norm()) {
    const double alpha = angle_about(h_perp, bd_perp, u);
    const double r = -h.dot(u) * bd.dot(u) / (h_perp.norm() * bd_perp.norm());
    double candidates[2] = {alpha, alpha - std::numbers::pi};
    int count = 1;
    if (std::abs(r) <= 1.0) {
      candidates[0] = alpha - std::acos(r);
      candidates[1] = alpha + std::acos(r);
      count = 2;
    } else if (r < 0) {
      candidates[0] = candidates[1];
    }
    double best = 0.0, best_outside = INFINITY, best_turn = INFINITY;
    for (int i = 0; i < count; ++i) {
      const double omega = candidates[i];
      const Eigen::Vector3d turned = Eigen::AngleAxisd(-omega, u) * bd;
      const double outside = flexion_outside(angle_about(g.bc, turned, h));
      const double size = std::abs(wrap(omega));
      if (outside < best_outside - 1e-12 || (outside <= best_outside + 1e-12 && size < best_turn)) {
        best = omega;
        best_outside = outside;
        best_turn = size;
      }
    }
    Eigen::Quaterniond a = pose.rotations[limb.a] * Eigen::AngleAxisd(best, u);
    pose.rotations[limb.a] = limits ? limits_.clamp(limb.a, a) : a;
    update(limb, pose, world);
  }
  // Lines 11-12: flex B to align BC with BD.
  const Eigen::Quaterniond flex(Eigen::AngleAxisd(angle_about(g.bc, to_b(), h), h));
  pose.rotations[limb.b] = limits ? limits_.clamp(limb.b, flex) : flex;
  update(limb, pose, world);
}

void SikLimbSolver::aim_from_neutral(const SikLimb& limb, const Geometry& g,
                                     const Eigen::Vector3d& target, bool limits, Pose& pose,
                                     SikWorld& world) const {
  // Always from the neutral stretched limb, so the swivel does not depend on earlier frames.
  pose.rotations[limb.a] = pose.rotations[limb.b] = Eigen::Quaterniond::Identity();
  update(limb, pose, world);
  const Eigen::Vector3d from_a = target - world.position[limb.a];
  const double phi = flexion_for_reach(limb, g, from_a.norm(), limits);
  const Eigen::Vector3d direction =
      from_a.norm() > kTiny
          ? Eigen::Vector3d(world.rotation[body_.parent(limb.a)].conjugate() * from_a)
          : Eigen::Vector3d(g.ab + g.bc);
  const Eigen::Quaterniond a = aim(g, phi, direction);
  pose.rotations[limb.a] = limits ? limits_.clamp(limb.a, a) : a;
  pose.rotations[limb.b] = Eigen::AngleAxisd(phi, g.hinge);
  update(limb, pose, world);
}

double SikLimbSolver::swivel_within_limits(const SikLimb& limb, double swivel, bool limits,
                                           Pose& pose, SikWorld& world) const {
  const Eigen::Vector3d line = world.position[limb.c] - world.position[limb.a];
  if (line.norm() < kTiny) return 0.0;
  const Eigen::Vector3d n = line.normalized();
  const Eigen::Quaterniond start = pose.rotations[limb.a];
  auto swivelled = [&](double t) {
    turn(limb.a, Eigen::Quaterniond(Eigen::AngleAxisd(t * swivel, n)), pose, world);
    const Eigen::Quaterniond q = pose.rotations[limb.a];
    pose.rotations[limb.a] = start;
    return q;
  };
  // Within the limits, the largest share of the swivel whose way there stays inside (A is inside
  // at the start): clamping A instead would move the end off its target.
  const double allowed = limits_.excess(limb.a, start) + kTiny;
  double t = 1.0;
  if (limits && limits_.excess(limb.a, swivelled(1.0)) > allowed) {
    double inside = 0.0, outside = 1.0;
    for (int i = 0; i < kSwivelBisections; ++i) {
      const double mid = 0.5 * (inside + outside);
      (limits_.excess(limb.a, swivelled(mid)) > allowed ? outside : inside) = mid;
    }
    t = inside;
  }
  pose.rotations[limb.a] = swivelled(t);
  update(limb, pose, world);
  return t * swivel;
}

void SikLimbSolver::follow_middle(const SikLimb& limb, const Eigen::Vector3d& middle, bool limits,
                                  Pose& pose, SikWorld& world) const {
  const Eigen::Vector3d a = world.position[limb.a];
  const Eigen::Vector3d line = world.position[limb.c] - a;
  if (line.norm() < kTiny) return;
  const Eigen::Vector3d n = line.normalized();
  const Eigen::Vector3d ab = world.position[limb.b] - a, am = middle - a;
  // A stretched limb or a middle target on the line has no swivel to follow.
  if ((ab - ab.dot(n) * n).norm() < kTiny || (am - am.dot(n) * n).norm() < kTiny) return;
  swivel_within_limits(limb, angle_about(ab, am, n), limits, pose, world);
}

void SikLimbSolver::least_rotation_swivel(const SikLimb& limb, bool limits, Pose& pose,
                                          SikWorld& world) const {
  const Eigen::Vector3d line = world.position[limb.c] - world.position[limb.a];
  if (line.norm() < kTiny) return;
  const Eigen::Vector3d n = line.normalized();
  const Eigen::Quaterniond start = pose.rotations[limb.a];
  const Eigen::Quaterniond& parent = world.rotation[body_.parent(limb.a)];
  const double allowed = limits_.excess(limb.a, start) + kTiny;
  // f(phi) = swing^2 + twist^2 of A (weight 1, §4.7.1), and whether A stays within its limits.
  auto cost = [&](double phi) {
    const Eigen::Quaterniond q = parent.conjugate() * Eigen::AngleAxisd(phi, n) * parent * start;
    const SwingTwist st = limits_.decompose(limb.a, q);
    const bool inside = !limits || limits_.excess(limb.a, q) <= allowed;
    return std::pair{inside ? 0 : 1, st.psi * st.psi + st.twist * st.twist};
  };
  // The global minimum over the whole turn (there may be several local ones): a grid, then a
  // golden-section search in the best cell.
  const double step = 2 * std::numbers::pi / kSwivelSamples;
  double best = 0.0;
  auto best_cost = cost(0.0);
  for (int k = 1; k < kSwivelSamples; ++k) {
    const auto c = cost(k * step - std::numbers::pi);
    if (c < best_cost) {
      best = k * step - std::numbers::pi;
      best_cost = c;
    }
  }
  constexpr double kGolden = 0.6180339887498949;
  double lo = best - step, hi = best + step;
  for (int i = 0; i < kSwivelRefinements; ++i) {
    const double x1 = hi - kGolden * (hi - lo), x2 = lo + kGolden * (hi - lo);
    if (cost(x1) < cost(x2)) {
      hi = x2;
    } else {
      lo = x1;
    }
  }
  const double refined = 0.5 * (lo + hi);
  if (cost(refined) < best_cost) best = refined;
  swivel_within_limits(limb, best, limits, pose, world);
}

void SikLimbSolver::choose_swivel(const SikLimb& limb, bool is_arm,
                                  const std::optional<Eigen::Vector3d>& middle, bool limits,
                                  Pose& pose, SikWorld& world) const {
  if (middle) {
    follow_middle(limb, *middle, limits, pose, world);
    return;
  }
  switch (swivel_) {
    case SikSwivel::neutral:
      return;
    case SikSwivel::least_rotation:
      least_rotation_swivel(limb, limits, pose, world);
      return;
    case SikSwivel::reference:
      break;
  }
  const Eigen::Matrix3d pelvis = world.rotation[body_.root()].toRotationMatrix();
  const Eigen::Vector3d first = is_arm ? Eigen::Vector3d(-pelvis.col(1)) : pelvis.col(2);
  const Eigen::Vector3d second = is_arm ? Eigen::Vector3d(-pelvis.col(2)) : pelvis.col(1);
  // The second reference when the first is in line with the limb (it then says nothing).
  constexpr double kInLine = 1e-3;  // sine of the angle between the limb and the reference
  const Eigen::Vector3d a = world.position[limb.a];
  const Eigen::Vector3d line = (world.position[limb.c] - a).normalized();
  follow_middle(limb, a + (line.cross(first).norm() > kInLine ? first : second), limits, pose,
                world);
}

void SikLimbSolver::place_limb(const SikLimb& limb, const Geometry& g, int side, bool is_arm,
                               const Eigen::Vector3d& target,
                               const std::optional<Eigen::Vector3d>& middle, bool limits,
                               Pose& pose, SikWorld& world) const {
  aim_from_neutral(limb, g, target, limits, pose, world);
  // A measured elbow is outside the torso: §4.6.1's swivel away from it would only fight it.
  if (is_arm && collider_ && !middle) clear_elbow(limb, side, target, limits, pose, world);
  bend_toward(limb, g, target, limits, pose, world);
  choose_swivel(limb, is_arm, middle, limits, pose, world);
  if (!collider_) return;
  if (is_arm) {
    clear_wrist(limb, side, limits, pose, world);
    return;
  }
  // §4.6.3 needs the foot's pose, which SIK's input does not give; with the ankle unturned the
  // foot would follow the calf and dig its toes into the floor whenever the knee bends. So with
  // floor collisions on, simcap keeps the foot level, heading where the pelvis heads.
  level_foot(limb, pose, world);
  // Then re-solve the leg, limits ignored, toward the ankle lifted by the foot's depth in the
  // floor (the thesis does this once; it is repeated while the foot is still in the floor).
  for (int i = 0; i < kMaxCollisionIterations; ++i) {
    const Eigen::Vector3d lowest =
        collider_->lowest_foot_point(side, world.rotation[limb.c], world.position[limb.c]);
    const double depth = collider_->floor_y() - lowest.y();
    if (depth <= kFloorTolerance) return;
    const Eigen::Vector3d lifted = world.position[limb.c] + Eigen::Vector3d(0.0, depth, 0.0);
    aim_from_neutral(limb, g, lifted, false, pose, world);
    bend_toward(limb, g, lifted, false, pose, world);
    choose_swivel(limb, is_arm, middle, false, pose, world);
    level_foot(limb, pose, world);
  }
}

void SikLimbSolver::level_foot(const SikLimb& leg, Pose& pose, SikWorld& world) const {
  const Eigen::Vector3d front = world.rotation[body_.root()] * Eigen::Vector3d::UnitZ();
  const Eigen::Quaterniond level(
      Eigen::AngleAxisd(std::atan2(front.x(), front.z()), Eigen::Vector3d::UnitY()));
  pose.rotations[leg.c] = (world.rotation[leg.b].conjugate() * level).normalized();
  update(leg, pose, world);
}

void SikLimbSolver::clear_elbow(const SikLimb& limb, int side, const Eigen::Vector3d& target,
                                bool limits, Pose& pose, SikWorld& world) const {
  const double radius = collider_->elbow_radius(side);
  for (int i = 0; i < kMaxCollisionIterations; ++i) {
    const SikPenetration pen =
        collider_->torso(world.rotation, world.position, world.position[limb.b], radius);
    if (pen.depth <= kClear) return;
    const Eigen::Vector3d a = world.position[limb.a];
    const Eigen::Vector3d ab = world.position[limb.b] - a;
    const Eigen::Vector3d line = (target - a).normalized();
    Eigen::Quaterniond world_turn;
    if ((ab - ab.dot(line) * line).norm() < radius) {
      // §4.6.1, stretched arm: turn the upper arm from p_e toward p_t as seen from the shoulder
      // (a lower bound of the turn needed, hence the iterations).
      const Eigen::Vector3d v = (pen.deepest - a).normalized(), w = (pen.outer - a).normalized();
      const Eigen::Vector3d axis = v.cross(w);
      if (axis.norm() < kTiny) return;
      world_turn = Eigen::AngleAxisd(std::acos(std::clamp(v.dot(w), -1.0, 1.0)), axis.normalized());
    } else {
      // §4.6.1, bent arm: swivel about the shoulder-target line, the way that moves the elbow
      // out along p_e -> p_t.
      const double sign = line.cross(ab).dot(pen.outer - pen.deepest) >= 0 ? 1.0 : -1.0;
      world_turn = Eigen::AngleAxisd(sign * kSwivelGain * pen.depth / ab.norm(), line);
    }
    turn(limb.a, world_turn, pose, world);
    if (limits) pose.rotations[limb.a] = limits_.clamp(limb.a, pose.rotations[limb.a]);
    update(limb, pose, world);
  }
}

void SikLimbSolver::clear_wrist(const SikLimb& limb, int side, bool limits, Pose& pose,
                                SikWorld& world) const {
  const double radius = collider_->wrist_radius(side);
  for (int i = 0; i < kMaxCollisionIterations; ++i) {
    const SikPenetration pen =
        collider_->torso(world.rotation, world.position, world.position[limb.c], radius);
    if (pen.depth <= kClear) return;
    // §4.6.2: aim the arm, as Alg. 13 line 2 does, at the wrist pushed out by p_t - p_e.
    const Eigen::Vector3d a = world.position[limb.a];
    const Eigen::Vector3d objective = world.position[limb.c] + (pen.outer - pen.deepest);
    turn(limb.a, Eigen::Quaterniond::FromTwoVectors(world.position[limb.c] - a, objective - a),
         pose, world);
    if (limits) pose.rotations[limb.a] = limits_.clamp(limb.a, pose.rotations[limb.a]);
    update(limb, pose, world);
    clear_elbow(limb, side, objective, limits, pose, world);
  }
}

void SikLimbSolver::place_arm(int side, const Eigen::Vector3d& target,
                              const std::optional<Eigen::Vector3d>& middle, bool limits, Pose& pose,
                              SikWorld& world) const {
  place_limb(body_.arm(side), arm_[side], side, true, target, middle, limits, pose, world);
}

void SikLimbSolver::place_leg(int side, const Eigen::Vector3d& target,
                              const std::optional<Eigen::Vector3d>& middle, bool limits, Pose& pose,
                              SikWorld& world) const {
  place_limb(body_.leg(side), leg_[side], side, false, target, middle, limits, pose, world);
}

void SikLimbSolver::place_clavicle(int side, const Eigen::Vector3d& wrist_target, bool limits,
                                   Pose& pose, SikWorld& world) const {
  const SikLimb& arm = body_.arm(side);
  const int st = arm.clavicle;
  if (st < 0) return;
  auto update_clavicle = [&] {
    const int p = body_.parent(st);
    world.rotation[st] = world.rotation[p] * pose.rotations[st];
    world.position[st] = world.position[p] + world.rotation[p] * body_.offset(st);
  };
  pose.rotations[st] = Eigen::Quaterniond::Identity();
  update_clavicle();
  // L1: the arm's longest reach within its limits; L2: shoulder to target (Fig. 36).
  const Geometry& g = arm_[side];
  const double phi = flexion_for_reach(arm, g, INFINITY, limits);
  const double reach = std::sqrt(std::max(g.c0 + 2 * g.m * std::cos(phi + g.delta), 0.0));
  const Eigen::Vector3d clavicle = world.rotation[st] * body_.offset(arm.a);
  const Eigen::Vector3d to_target = wrist_target - world.position[st];
  if ((to_target - clavicle).norm() <= reach) return;
  // theta1: the clavicle-target angle at which the stretched arm just reaches (cosine theorem);
  // theta2: the current one. Turn the clavicle by their difference toward the target.
  const double c = clavicle.norm(), e = to_target.norm();
  if (c < kTiny || e < kTiny) return;
  const double theta1 =
      std::acos(std::clamp((c * c + e * e - reach * reach) / (2 * c * e), -1.0, 1.0));
  const double theta2 = std::acos(std::clamp(clavicle.dot(to_target) / (c * e), -1.0, 1.0));
  const Eigen::Vector3d axis = clavicle.cross(to_target);
  if (theta2 <= theta1 || axis.norm() < kTiny) return;
  turn(st, Eigen::Quaterniond(Eigen::AngleAxisd(theta2 - theta1, axis.normalized())), pose, world);
  if (limits) pose.rotations[st] = limits_.clamp(st, pose.rotations[st]);
  update_clavicle();
}

}  // namespace simcap
