#include "tracker/unzueta/sik_limits.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double deg(double d) {
  return d * kPi / 180.0;
}

// Clinical ranges of motion, degrees, from the neutral standing posture. The thesis (§4.5) asks
// for "a reduced set of biomechanical limits that can be obtained from books such as Kapandji's"
// without a table; simcap uses the standard clinical table of the American Academy of Orthopaedic
// Surgeons, "Joint Motion: Method of Measuring and Recording" (AAOS, 1965; reprinted in Greene &
// Heckman, "The Clinical Measurement of Joint Motion", AAOS 1994), written [AAOS] below, and
// D. A. Neumann, "Kinesiology of the Musculoskeletal System", 2nd ed. (2010), ch. 5, for the
// sternoclavicular joint, written [Neumann].
//
// A cone lists (theta, psi_max): theta = 0 anterior, +90 lateral (limbs) or superior (clavicle),
// +-180 posterior, -90 medial or inferior.

// Shoulder complex [AAOS]: flexion 180, extension 60, abduction 180, adduction 75 (across the
// front of the trunk), horizontal flexion 135 and horizontal extension 45 measured from 90
// degrees of abduction (so at psi = 90 the arm reaches theta = 90 - 135 = -45 and
// theta = 90 + 45 = 135). Flexion and abduction are capped at 170: the swing-twist split is
// singular at the pole's antipode (arm straight up), and the last 10 degrees need trunk motion.
const std::vector<std::pair<double, double>> kShoulderCone = {
    {-180, 60}, {-90, 75}, {-45, 90}, {0, 170}, {90, 170}, {135, 90}, {180, 60}};
constexpr double kShoulderInternal = 70, kShoulderExternal = 90;  // [AAOS]

// Hip [AAOS]: flexion 120, extension 30, abduction 45, adduction 30; rotation 45 each way.
const std::vector<std::pair<double, double>> kHipCone = {
    {-180, 30}, {-90, 30}, {0, 120}, {90, 45}, {180, 30}};
constexpr double kHipInternal = 45, kHipExternal = 45;  // [AAOS]

// Elbow flexion 0..150 and knee flexion 0..135 [AAOS].
constexpr double kElbowFlexion = 150, kKneeFlexion = 135;

// Sternoclavicular joint [Neumann]: elevation 45, depression 10, protraction 15-20 (20 used),
// retraction 15-30 (30 used); posterior rotation 20-35 (35 used, allowed both ways: SIK only turns
// the clavicle about axes across it, so its twist stays near zero).
const std::vector<std::pair<double, double>> kClavicleCone = {
    {-180, 30}, {-90, 10}, {0, 20}, {90, 45}, {180, 30}};
constexpr double kClavicleTwist = 35;

// Spine, totals of a region [AAOS]: thoracic and lumbar spine flexion 80, extension 25, lateral
// bending 35, rotation 45; cervical spine flexion 45, extension 45, lateral bending 45, rotation
// 60. Each region's total is shared equally by the skeleton's joints in it (H-Anim vl*/vt* are
// thoracolumbar, vc* cervical), as the thesis' spine model spreads bending evenly.
struct SpineRegion {
  double flexion, extension, lateral, rotation;
};
constexpr SpineRegion kThoracolumbar = {80, 25, 35, 45};
constexpr SpineRegion kCervical = {45, 45, 45, 60};

std::vector<std::pair<double, double>> to_radians(
    const std::vector<std::pair<double, double>>& cone) {
  std::vector<std::pair<double, double>> out;
  for (const auto& [theta, psi] : cone) out.emplace_back(deg(theta), deg(psi));
  return out;
}

double wrap(double a) {
  a = std::remainder(a, 2 * kPi);
  return a <= -kPi ? a + 2 * kPi : a;
}

// Clamps an angle to [lo, hi] on the circle: outside, the nearer bound wins.
double clamp_angle(double a, double lo, double hi) {
  if (a >= lo && a <= hi) return a;
  return std::abs(wrap(a - lo)) <= std::abs(wrap(a - hi)) ? lo : hi;
}

double twist_about(const Eigen::Quaterniond& q, const Eigen::Vector3d& axis) {
  return wrap(2.0 * std::atan2(q.vec().dot(axis), q.w()));
}

Eigen::Vector3d perpendicular(const Eigen::Vector3d& v, const Eigen::Vector3d& pole) {
  return (v - v.dot(pole) * pole).normalized();
}

}  // namespace

SikLimits::SikLimits(const SikBody& body) : joints_(body.size()) {
  auto add_cone = [&](const std::vector<std::pair<double, double>>& cone) {
    cones_.emplace_back(to_radians(cone));
    return static_cast<int>(cones_.size()) - 1;
  };
  // A ball joint whose theta = 90 direction is `ninety` (made perpendicular to the pole).
  auto ball = [&](int j, int cone, const Eigen::Vector3d& ninety, double lo, double hi) {
    SikJointLimit& l = joints_[j];
    l.kind = SikLimitKind::ball;
    l.pole = body.segment_direction(j);
    l.theta_zero = perpendicular(Eigen::Vector3d::UnitZ(), l.pole);
    l.theta_ninety = perpendicular(ninety - ninety.dot(l.theta_zero) * l.theta_zero, l.pole);
    l.cone = cone;
    l.min = deg(lo);
    l.max = deg(hi);
  };
  // Limb twist: internal rotation turns the front of the limb toward the midline.
  auto limb = [&](int j, int cone, const Eigen::Vector3d& lateral, double internal,
                  double external) {
    ball(j, cone, lateral, 0, 0);
    SikJointLimit& l = joints_[j];
    const bool positive_is_internal = l.pole.cross(l.theta_zero).dot(-lateral) > 0;
    l.min = deg(positive_is_internal ? -external : -internal);
    l.max = deg(positive_is_internal ? internal : external);
  };
  auto hinge = [&](int j, const Eigen::Vector3d& axis, double flexion) {
    SikJointLimit& l = joints_[j];
    l.kind = SikLimitKind::hinge;
    l.pole = axis;
    l.min = 0.0;
    l.max = deg(flexion);
  };

  const int shoulder = add_cone(kShoulderCone), hip = add_cone(kHipCone),
            clavicle = add_cone(kClavicleCone);
  for (int side : {kLeft, kRight}) {
    const Eigen::Vector3d lateral(side == kLeft ? 1.0 : -1.0, 0.0, 0.0);
    const SikLimb& arm = body.arm(side);
    const SikLimb& leg = body.leg(side);
    limb(arm.a, shoulder, lateral, kShoulderInternal, kShoulderExternal);
    limb(leg.a, hip, lateral, kHipInternal, kHipExternal);
    hinge(arm.b, arm.hinge_axis, kElbowFlexion);
    hinge(leg.b, leg.hinge_axis, kKneeFlexion);
    if (arm.clavicle >= 0) {
      ball(arm.clavicle, clavicle, Eigen::Vector3d::UnitY(), -kClavicleTwist, kClavicleTwist);
    }
  }

  // Spine: every chain joint but the root (which SIK orients freely) gets its region's share.
  int thoracolumbar = 0, cervical = 0;
  const auto& spine = body.spine();
  auto is_cervical = [&](int j) { return body.skeleton()[j].name.starts_with("vc"); };
  for (size_t i = 1; i < spine.size(); ++i) ++(is_cervical(spine[i]) ? cervical : thoracolumbar);
  auto region_cone = [&](const SpineRegion& r, int count) {
    const double k = 1.0 / std::max(count, 1);
    return add_cone({{-180, r.extension * k},
                     {-90, r.lateral * k},
                     {0, r.flexion * k},
                     {90, r.lateral * k},
                     {180, r.extension * k}});
  };
  const int tl_cone = region_cone(kThoracolumbar, thoracolumbar);
  const int c_cone = region_cone(kCervical, cervical);
  for (size_t i = 1; i < spine.size(); ++i) {
    const int j = spine[i];
    if (body.segment_direction(j).isZero()) continue;
    const bool c = is_cervical(j);
    const double twist =
        (c ? kCervical.rotation / cervical : kThoracolumbar.rotation / thoracolumbar);
    ball(j, c ? c_cone : tl_cone, Eigen::Vector3d::UnitX(), -twist, twist);
  }
}

double SikLimits::max_swing(int joint, double theta) const {
  return cones_[joints_[joint].cone].max_swing(theta);
}

SwingTwist SikLimits::decompose(int joint, const Eigen::Quaterniond& q) const {
  const SikJointLimit& l = joints_[joint];
  const Eigen::Vector3d d = q * l.pole;
  SwingTwist st;
  st.psi = std::acos(std::clamp(d.dot(l.pole), -1.0, 1.0));
  st.theta = std::atan2(d.dot(l.theta_ninety), d.dot(l.theta_zero));
  const Eigen::Quaterniond swing = Eigen::Quaterniond::FromTwoVectors(l.pole, d);
  st.twist = twist_about(swing.conjugate() * q, l.pole);
  return st;
}

Eigen::Quaterniond SikLimits::clamp(int joint, const Eigen::Quaterniond& q) const {
  const SikJointLimit& l = joints_[joint];
  switch (l.kind) {
    case SikLimitKind::free:
      return q;
    case SikLimitKind::hinge:
      return Eigen::Quaterniond(
          Eigen::AngleAxisd(clamp_angle(twist_about(q, l.pole), l.min, l.max), l.pole));
    case SikLimitKind::ball:
      break;
  }
  const SwingTwist st = decompose(joint, q);
  const double psi_max = max_swing(joint, st.theta);
  const double twist = clamp_angle(st.twist, l.min, l.max);
  if (st.psi <= psi_max && twist == st.twist) return q;
  Eigen::Vector3d d = q * l.pole;
  if (st.psi > psi_max) {
    d = std::cos(psi_max) * l.pole + std::sin(psi_max) * (std::cos(st.theta) * l.theta_zero +
                                                          std::sin(st.theta) * l.theta_ninety);
  }
  return Eigen::Quaterniond::FromTwoVectors(l.pole, d) *
         Eigen::Quaterniond(Eigen::AngleAxisd(twist, l.pole));
}

double SikLimits::excess(int joint, const Eigen::Quaterniond& q) const {
  const SikJointLimit& l = joints_[joint];
  auto outside = [&](double a) {
    if (a >= l.min && a <= l.max) return 0.0;
    return std::min(std::abs(wrap(a - l.min)), std::abs(wrap(a - l.max)));
  };
  switch (l.kind) {
    case SikLimitKind::free:
      return 0.0;
    case SikLimitKind::hinge: {
      const double angle = twist_about(q, l.pole);
      const Eigen::Quaterniond off = q * Eigen::Quaterniond(Eigen::AngleAxisd(-angle, l.pole));
      return std::max(outside(angle), Eigen::AngleAxisd(off).angle());
    }
    case SikLimitKind::ball:
      break;
  }
  const SwingTwist st = decompose(joint, q);
  return std::max(std::max(st.psi - max_swing(joint, st.theta), 0.0), outside(st.twist));
}

}  // namespace simcap
