#include "models/joint_limits.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/shipped_assets.h"
#include "models/urdf_io.h"

namespace simcap {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double deg(double d) {
  return d * kPi / 180.0;
}

const Eigen::Vector3d kX = Eigen::Vector3d::UnitX();
const Eigen::Vector3d kY = Eigen::Vector3d::UnitY();
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// A DOF whose limits are a source's range converted by angle = sign * source_angle + offset.
DofLimit converted(std::string name, const Eigen::Vector3d& axis, double source_lower,
                   double source_upper, double sign, double offset, std::string source) {
  const double a = sign * source_lower + offset, b = sign * source_upper + offset;
  return {std::move(name), axis, std::min(a, b), std::max(a, b), std::move(source), sign, offset};
}

DofLimit direct(std::string name, const Eigen::Vector3d& axis, double lower, double upper,
                std::string source) {
  return converted(std::move(name), axis, lower, upper, 1.0, 0.0, std::move(source));
}

// Moschini's torso frame has X forward, Y to the left and Z up (Table 5.3: the head is at +Z,
// the left shoulder at +Y), so his X, Y, Z are simcap's Z, X, Y. His zero pose has the arms
// straight out to the sides: his shoulder chain R_x(t1) R_z(t2) R_y(t3) in his axes equals
// R_z(t1 + pi/2) R_x(t2) R_y(-t3) R_z(-pi/2) in simcap's, i.e. simcap's shoulder angles are
// (t1 + pi/2, t2, -t3) from the arm-down neutral pose, and the elbow's "Z shoulder" axis becomes
// +X. The right shoulder (1) range [0, 2 pi] is centred on pi (the right arm out to the side),
// so its offset is pi/2 - 2 pi. Legs and neck start from the same pose as simcap's.
std::vector<JointLimits> make_moschini() {
  const std::string t = "Moschini 2009 Table 5.1, ";
  auto m = [&](std::string name, const Eigen::Vector3d& axis, double lo, double hi,
               const std::string& what, double sign = 1.0, double offset = 0.0) {
    return converted(std::move(name), axis, lo, hi, sign, offset, t + what);
  };
  const double h = kPi / 2;
  return {
      {"vc7",
       {m("vc7_lateral", kZ, -h, h, "theta1 Neck(1), X torso [-pi/2, pi/2]"),
        m("vc7_flexion", kX, -h, h, "theta2 Neck(2), Y torso [-pi/2, pi/2]")}},
      {"l_hip",
       {m("l_hip_abduction", kZ, -kPi / 3, h, "theta11 Left Hip(1), X torso [-pi/3, pi/2]"),
        m("l_hip_flexion", kX, -kPi, h, "theta13 Left Hip(2), Y torso [-pi, pi/2]")}},
      {"l_knee", {m("l_knee_flexion", kX, 0, kPi, "theta15 Left Knee, Y hip [0, pi]")}},
      {"r_hip",
       {m("r_hip_abduction", kZ, -h, kPi / 3, "theta12 Right Hip(1), X torso [-pi/2, pi/3]"),
        m("r_hip_flexion", kX, -kPi, h, "theta14 Right Hip(2), Y torso [-pi, pi/2]")}},
      {"r_knee", {m("r_knee_flexion", kX, 0, kPi, "theta16 Right Knee, Y hip [0, pi]")}},
      {"l_shoulder",
       {m("l_shoulder_abduction", kZ, -kPi, kPi,
          "theta3 Left Shoulder(1), X torso [-pi, pi], +pi/2 (thesis zero: arm out sideways)", 1,
          h),
        m("l_shoulder_flexion", kX, -kPi, h, "theta5 Left Shoulder(2), Z torso [-pi, pi/2]"),
        m("l_shoulder_twist", kY, -h, 3 * kPi / 4,
          "theta7 Left Shoulder(3), Y shoulder [-pi/2, 3pi/4], negated", -1)}},
      {"l_elbow", {m("l_elbow_flexion", kX, -kPi, 0, "theta9 Left Elbow, Z shoulder [-pi, 0]")}},
      {"r_shoulder",
       {m("r_shoulder_abduction", kZ, 0, 2 * kPi,
          "theta4 Right Shoulder(1), X torso [0, 2pi], -3pi/2 (thesis zero: arm out sideways)", 1,
          h - 2 * kPi),
        m("r_shoulder_flexion", kX, -kPi, h, "theta6 Right Shoulder(2), Z torso [-pi, pi/2]"),
        m("r_shoulder_twist", kY, -3 * kPi / 4, h,
          "theta8 Right Shoulder(3), Y shoulder [-3pi/4, pi/2], negated", -1)}},
      {"r_elbow", {m("r_elbow_flexion", kX, -kPi, 0, "theta10 Right Elbow, Z shoulder [-pi, 0]")}},
  };
}

// Gomez Jauregui names the angles as MPEG-4 BAPs (Table 2-2) on an arms-down H-Anim model, whose
// axes are simcap's: flexion and tilt about X, abduct and roll about Z, twisting and torsion
// about Y. The wrist's flexion is about Z and its pivot about X because the palm faces the thigh.
// The thesis gives no axes or composition order; these are inferred from the BAP names.
std::vector<JointLimits> make_gomez() {
  const std::string t = "Gomez Jauregui 2011 Table 2-1, ";
  auto g = [&](std::string name, const Eigen::Vector3d& axis, double lo, double hi,
               const std::string& what) {
    return direct(std::move(name), axis, deg(lo), deg(hi), t + what);
  };
  return {
      {"vl5",
       {g("vl5_lateral", kZ, -45, 45, "#2 humanoid root roll (BAP vl5_roll) [-45, 45] deg"),
        g("vl5_flexion", kX, -45, 45, "#3 humanoid root tilt (BAP vl5_tilt) [-45, 45] deg"),
        g("vl5_twist", kY, -180, 180,
          "#1 humanoid root torsion (BAP vl5_torsion) [-180, 180] deg")}},
      {"skullbase",
       {g("skullbase_lateral", kZ, -10, 10, "#4 neck roll [-10, 10] deg"),
        g("skullbase_flexion", kX, -10, 10, "#6 neck tilt [-10, 10] deg"),
        g("skullbase_twist", kY, -10, 10, "#5 neck torsion [-10, 10] deg")}},
      {"l_shoulder",
       {g("l_shoulder_abduction", kZ, -20, 100, "#9 left shoulder abduct [-20, 100] deg"),
        g("l_shoulder_flexion", kX, -110, 25, "#7 left shoulder flexion [-110, 25] deg"),
        g("l_shoulder_twist", kY, -60, 30, "#8 left shoulder twisting [-60, 30] deg")}},
      {"l_elbow", {g("l_elbow_flexion", kX, -150, 0, "#13 left elbow flexion [-150, 0] deg")}},
      {"l_radiocarpal",
       {g("l_radiocarpal_flexion", kZ, -20, 20, "#15 left wrist flexion [-20, 20] deg"),
        g("l_radiocarpal_pivot", kX, -37, 27, "#17 left wrist pivot [-37, 27] deg"),
        g("l_radiocarpal_twist", kY, -100, 100, "#16 left wrist twisting [-100, 100] deg")}},
      {"r_shoulder",
       {g("r_shoulder_abduction", kZ, -100, 20, "#12 right shoulder abduct [-100, 20] deg"),
        g("r_shoulder_flexion", kX, -110, 25, "#10 right shoulder flexion [-110, 25] deg"),
        g("r_shoulder_twist", kY, -30, 60, "#11 right shoulder twisting [-30, 60] deg")}},
      {"r_elbow", {g("r_elbow_flexion", kX, -150, 0, "#14 right elbow flexion [-150, 0] deg")}},
      {"r_radiocarpal",
       {g("r_radiocarpal_flexion", kZ, -20, 20, "#18 right wrist flexion [-20, 20] deg"),
        g("r_radiocarpal_pivot", kX, -37, 27, "#20 right wrist pivot [-37, 27] deg"),
        g("r_radiocarpal_twist", kY, -100, 100, "#19 right wrist twisting [-100, 100] deg")}},
  };
}

std::string format(const char* fmt, double a, double b) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, a, b);
  return buf;
}

char axis_letter(const Eigen::Vector3d& axis) {
  if (axis == kX) return 'X';
  if (axis == kY) return 'Y';
  if (axis == kZ) return 'Z';
  throw Error("joint limits: a DOF axis must be +X, +Y or +Z");
}

}  // namespace

const std::vector<JointLimits>& moschini_joint_limits() {
  static const std::vector<JointLimits> table = make_moschini();
  return table;
}

const std::vector<JointLimits>& gomez_joint_limits() {
  static const std::vector<JointLimits> table = make_gomez();
  return table;
}

const std::filesystem::path& humanoid_limits_urdf() {
  static const std::filesystem::path path = asset_dir() / "humanoid_limits.urdf";
  return path;
}

const std::vector<JointLimits>& humanoid_joint_limits() {
  static const std::vector<JointLimits> table =
      read_urdf_limits(humanoid_limits_urdf(), build_humanoid());
  return table;
}

const JointLimits* find_joint_limits(const std::vector<JointLimits>& table,
                                     std::string_view joint) {
  for (const JointLimits& j : table) {
    if (j.joint == joint) return &j;
  }
  return nullptr;
}

Eigen::Quaterniond dof_rotation(const JointLimits& joint, std::span<const double> angles) {
  if (angles.size() != joint.dofs.size()) {
    throw Error("joint '" + joint.joint + "' has " + std::to_string(joint.dofs.size()) +
                " degrees of freedom, got " + std::to_string(angles.size()) + " angles");
  }
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (size_t i = 0; i < angles.size(); ++i) {
    q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angles[i], joint.dofs[i].axis));
  }
  return q;
}

std::vector<double> dof_angles(const JointLimits& joint, const Eigen::Quaterniond& rotation) {
  // R = R_z(a) R_x(b) R_y(c): row 2 is (-cos b sin c, sin b, cos b cos c) and column 1 is
  // (-sin a cos b, cos a cos b, sin b).
  const Eigen::Matrix3d r = rotation.normalized().toRotationMatrix();
  const double b = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  const double a = std::atan2(-r(0, 1), r(1, 1));
  const double c = std::atan2(-r(2, 0), r(2, 2));
  std::vector<double> out;
  for (const DofLimit& d : joint.dofs) {
    const char axis = axis_letter(d.axis);
    out.push_back(axis == 'Z' ? a : axis == 'X' ? b : c);
  }
  return out;
}

double limit_excess(const JointLimits& joint, const Eigen::Quaterniond& rotation) {
  const Eigen::Quaterniond q = rotation.normalized();
  const Eigen::Matrix3d r = q.toRotationMatrix();
  const double a = std::atan2(-r(0, 1), r(1, 1));
  const double b = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  const double c = std::atan2(-r(2, 0), r(2, 2));
  // R_z(a) R_x(b) R_y(c) = R_z(a + pi) R_x(pi - b) R_y(c + pi): both decompositions start a
  // search, each angle turned by whole turns to lie nearest its range.
  const std::array<std::array<double, 3>, 2> branches = {{{a, b, c}, {a + kPi, kPi - b, c + kPi}}};
  const size_t n = joint.dofs.size();
  const auto error = [&](const std::vector<double>& x) {
    const Eigen::AngleAxisd e(q.conjugate() * dof_rotation(joint, x));
    return Eigen::Vector3d(e.angle() * e.axis());
  };
  double best = INFINITY;
  for (const auto& euler : branches) {
    std::vector<double> x(n);
    for (size_t i = 0; i < n; ++i) {
      const DofLimit& d = joint.dofs[i];
      const char axis = axis_letter(d.axis);
      double v = euler[axis == 'Z' ? 0 : axis == 'X' ? 1 : 2];
      v += 2 * kPi * std::round((0.5 * (d.lower + d.upper) - v) / (2 * kPi));
      x[i] = std::clamp(v, d.lower, d.upper);
    }
    // Gauss-Newton on the rotation error over the angles not held at a limit they press
    // against: near gimbal lock (hip flexed 90 degrees) the Euler angles of a reachable rotation
    // may lie far outside the box while a rotation within it is a fraction of a degree away.
    for (int iteration = 0; iteration < 40 && n > 0; ++iteration) {
      const Eigen::Vector3d e = error(x);
      Eigen::MatrixXd jacobian(3, n);
      for (size_t i = 0; i < n; ++i) {
        std::vector<double> xi = x;
        xi[i] += 1e-7;
        jacobian.col(i) = (error(xi) - e) / 1e-7;
      }
      const Eigen::VectorXd gradient = jacobian.transpose() * e;
      for (size_t i = 0; i < n; ++i) {
        const DofLimit& d = joint.dofs[i];
        if ((x[i] <= d.lower && gradient[i] > 0) || (x[i] >= d.upper && gradient[i] < 0)) {
          jacobian.col(i).setZero();
        }
      }
      const Eigen::MatrixXd normal =
          jacobian.transpose() * jacobian + 1e-9 * Eigen::MatrixXd::Identity(n, n);
      const Eigen::VectorXd step = normal.ldlt().solve(-jacobian.transpose() * e);
      for (size_t i = 0; i < n; ++i) {
        x[i] = std::clamp(x[i] + step[i], joint.dofs[i].lower, joint.dofs[i].upper);
      }
    }
    best = std::min(best, error(x).norm());
  }
  return best;
}

std::string joint_limits_markdown(const std::vector<JointLimits>& table) {
  std::string out =
      "| H-Anim joint | DOF (URDF joint) | axis | lower (deg) | upper (deg) | lower (rad) | "
      "upper (rad) | source |\n"
      "|---|---|---|---|---|---|---|---|\n";
  for (const JointLimits& j : table) {
    for (const DofLimit& d : j.dofs) {
      out += "| " + j.joint + " | " + d.name + " | +" + axis_letter(d.axis) + " | " +
             format("%.1f | %.1f", d.lower * 180 / kPi, d.upper * 180 / kPi) + " | " +
             format("%.4f | %.4f", d.lower, d.upper) + " | " + d.source + " |\n";
    }
  }
  return out;
}

}  // namespace simcap
