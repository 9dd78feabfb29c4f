// The monocular tracker's DOF table and the state <-> pose conversions (body_dofs.h).
#include "tracker/gomez/body_dofs.h"

#include <cmath>
#include <numbers>

#include "core/error.h"
#include "models/joint_limits.h"
#include "models/mpeg4_bap.h"

namespace simcap::tracker::gomez {
namespace {

constexpr double kPi = std::numbers::pi;

int axis_index(const Eigen::Vector3d& axis) {
  if (axis.x() > 0.5) return 0;
  if (axis.y() > 0.5) return 1;
  return 2;
}

Eigen::Vector3d unit(int axis) {
  return Eigen::Vector3d::Unit(axis);
}

// Typical change per frame at 30 frames/s (simcap's choice, from the CMU clips' joint speeds:
// a walking arm swings about 1.5 rad/s, a knee about 4 rad/s at its fastest).
double step_of(const std::string& joint, bool translation) {
  if (translation) return 0.03;
  if (joint == "humanoid_root") return 0.04;
  if (joint == "vl5" || joint == "vc7" || joint == "skullbase") return 0.03;
  if (joint.ends_with("elbow") || joint.ends_with("knee")) return 0.10;
  return 0.08;
}

// The MPEG-4 BAP of a DOF: the BAP names use flexion/tilt about X, abduct/roll about Z and
// twisting/torsion about Y (models/joint_limits.cpp reads Table 2-2 the same way).
int bap_of(const std::string& joint, int axis) {
  const char* const joint_motion[3] = {"flexion", "twisting", "abduct"};
  const char* const spine_motion[3] = {"tilt", "torsion", "roll"};
  std::string name;
  if (joint == "humanoid_root") {
    const char* const root[3] = {"tilt", "turn", "roll"};
    name = std::string("HumanoidRoot_rt_body_") + root[axis];
  } else if (joint == "vl5" || joint == "vc7" || joint == "skullbase") {
    name = joint + "_" + spine_motion[axis];
  } else if (joint.ends_with("radiocarpal")) {
    const char* const wrist[3] = {"pivot", "twisting", "flexion"};
    name = joint.substr(0, 2) + "wrist_" + wrist[axis];
  } else if (joint.ends_with("talocrural")) {
    name = joint.substr(0, 2) + "ankle_flexion";
  } else {
    name = joint + "_" + joint_motion[axis];
  }
  const int id = bap_id(name);
  if (id == 0) throw Error("monocular body: no MPEG-4 BAP named '" + name + "'");
  return id;
}

Part part_of(const std::string& joint) {
  if (joint == "vc7" || joint == "skullbase") return Part::head;
  if (joint.starts_with("l_")) {
    return joint.ends_with("hip") || joint.ends_with("knee") || joint.ends_with("talocrural")
               ? Part::left_leg
               : Part::left_arm;
  }
  if (joint.starts_with("r_")) {
    return joint.ends_with("hip") || joint.ends_with("knee") || joint.ends_with("talocrural")
               ? Part::right_leg
               : Part::right_arm;
  }
  return Part::torso;
}

// R = R_a(x0) R_b(x1) R_c(x2) for the axis order (a, b, c), a permutation of X, Y, Z: its two
// Tait-Bryan solutions.
void tait_bryan(const Eigen::Matrix3d& R, int a, int b, int c, Eigen::Vector3d out[2]) {
  const bool cyclic = (b == (a + 1) % 3);
  const double e = cyclic ? 1.0 : -1.0;
  const double beta = std::asin(std::clamp(e * R(a, c), -1.0, 1.0));
  const double alpha = std::atan2(-e * R(b, c), R(c, c));
  const double gamma = std::atan2(-e * R(a, b), R(a, a));
  out[0] = {alpha, beta, gamma};
  out[1] = {alpha + kPi, kPi - beta, gamma + kPi};
}

}  // namespace

BodyDofs::BodyDofs(const Skeleton& skeleton, BodyKind kind, const Pose& first,
                   std::vector<FloorContact> floor, double reach_m)
    : skeleton_(&skeleton), kind_(kind), fixed_(first) {
  if (kind == BodyKind::full) floor_ = std::move(floor);
  if (kind == BodyKind::full) {
    // Joints without DOFs (the spine between vl5 and vc7, clavicles, toes) stay neutral.
    fixed_ = Pose::neutral(skeleton);
    fixed_.root_position = first.root_position;
  }
  joint_dofs_.assign(skeleton.size(), {});
  const auto add = [&](const std::string& joint_name, int axis, double lower, double upper,
                       const std::string& dof_name) {
    Dof d;
    d.name = dof_name;
    d.joint = skeleton.require(joint_name);
    d.axis = axis;
    d.lower = lower;
    d.upper = upper;
    d.step = step_of(joint_name, false);
    d.part = part_of(joint_name);
    d.bap = bap_of(joint_name, axis);
    joint_dofs_[d.joint].push_back(static_cast<int>(dofs_.size()));
    dofs_.push_back(d);
  };
  const auto add_table = [&](const std::vector<JointLimits>& table, const std::string& joint) {
    const JointLimits* limits = find_joint_limits(table, joint);
    if (!limits) throw Error("monocular body: no joint limits for " + joint);
    for (const DofLimit& l : limits->dofs) add(joint, axis_index(l.axis), l.lower, l.upper, l.name);
  };
  const auto& gomez = gomez_joint_limits();
  const auto& anatomy = humanoid_joint_limits();

  const int root = skeleton.require("humanoid_root");
  if (kind == BodyKind::full) {
    const char* const names[3] = {"root_tx", "root_ty", "root_tz"};
    for (int a = 0; a < 3; ++a) {
      if (a == 1 && !floor_.empty()) continue;
      Dof d;
      d.name = names[a];
      d.joint = root;
      d.axis = a;
      d.translation = true;
      d.lower = first.root_position[a] - reach_m;
      d.upper = first.root_position[a] + reach_m;
      d.step = step_of("humanoid_root", true);
      d.bap = bap_id(a == 0   ? "HumanoidRoot_tr_lateral"
                     : a == 1 ? "HumanoidRoot_tr_vertical"
                              : "HumanoidRoot_tr_frontal");
      dofs_.push_back(d);
    }
    // Heading first, so that the turn is about the world's vertical: R = R_y R_x R_z. Roll and
    // tilt keep Table 2-1's +-45 deg of the thesis's root; the turn may go round twice.
    const double turn = std::atan2(-(first.rotations[root] * Eigen::Vector3d::UnitX()).z(),
                                   (first.rotations[root] * Eigen::Vector3d::UnitX()).x());
    add("humanoid_root", 1, turn - 4 * kPi, turn + 4 * kPi, "root_turn");
    add("humanoid_root", 0, -kPi / 4, kPi / 4, "root_tilt");
    add("humanoid_root", 2, -kPi / 4, kPi / 4, "root_roll");
    // The trunk bends at vl5 by as much as the six spine joints vl5..vt1 together (AAOS), the
    // neck at vc7 by as much as vc7, vc4 and skullbase together (AAOS: 3 x skullbase's range).
    const JointLimits* spine = find_joint_limits(anatomy, "vl5");
    const JointLimits* neck = find_joint_limits(anatomy, "skullbase");
    for (const DofLimit& l : spine->dofs) {
      add("vl5", axis_index(l.axis), 6 * l.lower, 6 * l.upper, l.name);
    }
    for (const DofLimit& l : neck->dofs) {
      add("vc7", axis_index(l.axis), 3 * l.lower, 3 * l.upper,
          "vc7" + l.name.substr(std::string("skullbase").size()));
    }
  } else {
    add_table(gomez, "vl5");
    add_table(gomez, "skullbase");
  }
  for (const char* side : {"l_", "r_"}) {
    const std::string s = side;
    add_table(gomez, s + "shoulder");
    add_table(gomez, s + "elbow");
    add_table(gomez, s + "radiocarpal");
  }
  if (kind == BodyKind::full) {
    for (const char* side : {"l_", "r_"}) {
      const std::string s = side;
      add_table(anatomy, s + "hip");
      add_table(anatomy, s + "knee");
      const JointLimits* ankle = find_joint_limits(anatomy, s + "talocrural");
      for (const DofLimit& l : ankle->dofs) {
        if (axis_index(l.axis) == 0) add(s + "talocrural", 0, l.lower, l.upper, l.name);
      }
    }
  }
}

int BodyDofs::find(std::string_view name) const {
  for (int i = 0; i < size(); ++i) {
    if (dofs_[i].name == name) return i;
  }
  return -1;
}

int BodyDofs::require(std::string_view name) const {
  const int i = find(name);
  if (i < 0) throw Error("monocular body: no DOF '" + std::string(name) + "'");
  return i;
}

std::vector<int> BodyDofs::part_dofs(Part part) const {
  std::vector<int> out;
  for (int i = 0; i < size(); ++i) {
    if (dofs_[i].part == part) out.push_back(i);
  }
  return out;
}

Pose BodyDofs::pose(const State& x) const {
  Pose p = fixed_;
  for (int j = 0; j < skeleton_->size(); ++j) {
    const auto& list = joint_dofs_[j];
    if (list.empty()) continue;
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    for (const int i : list)
      q = q * Eigen::Quaterniond(Eigen::AngleAxisd(x[i], unit(dofs_[i].axis)));
    p.rotations[j] = q;
  }
  for (int i = 0; i < size(); ++i) {
    if (dofs_[i].translation) p.root_position[dofs_[i].axis] = x[i];
  }
  if (!floor_.empty()) {
    p.root_position.y() = 0;
    const auto g = forward_kinematics(*skeleton_, p);
    double low = INFINITY;
    for (const FloorContact& c : floor_) low = std::min(low, (g[c.joint] * c.point).y());
    p.root_position.y() = -low;
  }
  return p;
}

void BodyDofs::set_joint(int joint, const Eigen::Quaterniond& rotation, State& x) const {
  const auto& list = joint_dofs_[joint];
  if (list.empty()) return;
  const Eigen::Matrix3d R = rotation.toRotationMatrix();
  const auto wrap_near = [](double a, double near) {
    return near + std::remainder(a - near, 2 * kPi);
  };
  if (list.size() == 1) {
    // The twist of the rotation about the DOF's axis (swing-twist decomposition).
    const int i = list[0];
    const Eigen::Quaterniond q = rotation.normalized();
    const double along = q.vec()[dofs_[i].axis];
    x[i] = wrap_near(2 * std::atan2(along, q.w()), x[i]);
    return;
  }
  // Complete the joint's axis order to a permutation of X, Y, Z (missing axes last).
  int order[3], n = 0;
  for (const int i : list) order[n++] = dofs_[i].axis;
  for (int a = 0; a < 3 && n < 3; ++a) {
    bool used = false;
    for (int k = 0; k < n; ++k) used = used || order[k] == a;
    if (!used) order[n++] = a;
  }
  Eigen::Vector3d sol[2];
  tait_bryan(R, order[0], order[1], order[2], sol);
  double best_cost = INFINITY;
  Eigen::Vector3d best = sol[0];
  for (Eigen::Vector3d& s : sol) {
    double outside = 0, distance = 0;
    for (size_t k = 0; k < list.size(); ++k) {
      const Dof& d = dofs_[list[k]];
      s[k] = wrap_near(s[k], x[list[k]]);
      outside += std::max(0.0, d.lower - s[k]) + std::max(0.0, s[k] - d.upper);
      distance += std::abs(s[k] - x[list[k]]);
    }
    const double cost = 1e3 * outside + distance;
    if (cost < best_cost) {
      best_cost = cost;
      best = s;
    }
  }
  for (size_t k = 0; k < list.size(); ++k) x[list[k]] = best[k];
}

State BodyDofs::state_of(const Pose& pose, const State& near) const {
  State x = near;
  for (int j = 0; j < skeleton_->size(); ++j) set_joint(j, pose.rotations[j], x);
  for (int i = 0; i < size(); ++i) {
    if (dofs_[i].translation) x[i] = pose.root_position[dofs_[i].axis];
  }
  return x;
}

State BodyDofs::clamp(State x) const {
  for (int i = 0; i < size(); ++i) x[i] = std::clamp(x[i], dofs_[i].lower, dofs_[i].upper);
  return x;
}

bool BodyDofs::inside(const State& x, double slack) const {
  for (int i = 0; i < size(); ++i) {
    if (x[i] < dofs_[i].lower - slack || x[i] > dofs_[i].upper + slack) return false;
  }
  return true;
}

State BodyDofs::steps() const {
  State s(size());
  for (int i = 0; i < size(); ++i) s[i] = dofs_[i].step;
  return s;
}

State BodyDofs::lower() const {
  State s(size());
  for (int i = 0; i < size(); ++i) s[i] = dofs_[i].lower;
  return s;
}

State BodyDofs::upper() const {
  State s(size());
  for (int i = 0; i < size(); ++i) s[i] = dofs_[i].upper;
  return s;
}

}  // namespace simcap::tracker::gomez
