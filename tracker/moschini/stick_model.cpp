#include "tracker/moschini/stick_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/joint_limits.h"

namespace simcap::tracker {
namespace {

constexpr double kPi = std::numbers::pi;

double wrap(double a) {  // to (-π, π]
  a = std::remainder(a, 2 * kPi);
  return a <= -kPi ? a + 2 * kPi : a;
}

// The joint that places each segment relative to its parent (pelvis: none): its H-Anim name in
// models/joint_limits.h ("spine" lumps the thoracolumbar joints) and which angles its DOFs are,
// outermost first.
struct JointSpec {
  const char* name;
  int count;
  std::array<int, 3> angles;
};
using JointTable = std::array<JointSpec, kSegmentCount>;

const JointTable& joint_specs(JointSet set) {
  static constexpr JointTable moschini = {{
      {"", 0, {}},
      {"spine", 0, {}},
      {"vc7", 2, {kNeck1, kNeck2}},
      {"l_shoulder", 3, {kLShoulder1, kLShoulder2, kLShoulder3}},
      {"l_elbow", 1, {kLElbow}},
      {"l_radiocarpal", 0, {}},
      {"r_shoulder", 3, {kRShoulder1, kRShoulder2, kRShoulder3}},
      {"r_elbow", 1, {kRElbow}},
      {"r_radiocarpal", 0, {}},
      {"l_hip", 2, {kLHip1, kLHip2}},
      {"l_knee", 1, {kLKnee}},
      {"l_talocrural", 0, {}},
      {"r_hip", 2, {kRHip1, kRHip2}},
      {"r_knee", 1, {kRKnee}},
      {"r_talocrural", 0, {}},
  }};
  static constexpr JointTable urdf = [] {
    JointTable t = moschini;
    t[kChest] = {"spine", 3, {kSpineLateral, kSpineFlexion, kSpineTwist}};
    t[kLThigh] = {"l_hip", 3, {kLHip1, kLHip2, kLHipTwist}};
    t[kRThigh] = {"r_hip", 3, {kRHip1, kRHip2, kRHipTwist}};
    t[kLFoot] = {"l_talocrural", 1, {kLAnkle}};
    t[kRFoot] = {"r_talocrural", 1, {kRAnkle}};
    t[kLHand] = {"l_radiocarpal", 2, {kLWristFlexion, kLWristDeviation}};
    t[kRHand] = {"r_radiocarpal", 2, {kRWristFlexion, kRWristDeviation}};
    return t;
  }();
  return set == JointSet::moschini ? moschini : urdf;
}

// The thoracolumbar joints as one: per axis, the sum of their ranges.
JointLimits lumped_spine(const std::vector<JointLimits>& source) {
  JointLimits spine{"spine", {}};
  for (const char* name : {"vl5", "vl3", "vl1", "vt10", "vt6", "vt1"}) {
    const JointLimits* joint = find_joint_limits(source, name);
    if (!joint) {
      throw Error(std::string("stick model: models/joint_limits.h has no entry for '") + name +
                  "'");
    }
    for (const DofLimit& dof : joint->dofs) {
      auto it = std::find_if(spine.dofs.begin(), spine.dofs.end(),
                             [&](const DofLimit& d) { return d.axis == dof.axis; });
      if (it == spine.dofs.end()) {
        spine.dofs.push_back({"spine", dof.axis, 0.0, 0.0, "sum of vl5..vt1"});
        it = spine.dofs.end() - 1;
      }
      it->lower += dof.lower;
      it->upper += dof.upper;
    }
  }
  return spine;
}

AngleTable make_angle_table(JointSet set, const std::vector<JointLimits>& urdf_limits) {
  const std::vector<JointLimits>& source =
      set == JointSet::moschini ? simcap::moschini_joint_limits() : urdf_limits;
  // The axes set_segment_rotation() solves for, by DOF count: X (hinge), Z X (swing), Z X Y.
  static constexpr std::array<std::array<int, 3>, 4> order = {{{}, {0}, {2, 0}, {2, 0, 1}}};
  AngleTable t;
  const JointTable& specs = joint_specs(set);
  for (int s = 1; s < kSegmentCount; ++s) {
    const JointSpec& spec = specs[s];
    if (spec.count == 0) continue;
    const JointLimits spine =
        spec.name == std::string_view("spine") ? lumped_spine(source) : JointLimits{};
    const JointLimits* limits = spine.dofs.empty() ? find_joint_limits(source, spec.name) : &spine;
    for (int i = 0; i < spec.count; ++i) {
      const int axis = order[spec.count][i];
      const auto dof = limits ? std::find_if(limits->dofs.begin(), limits->dofs.end(),
                                             [&](const DofLimit& d) {
                                               return d.axis == Eigen::Vector3d::Unit(axis);
                                             })
                              : std::vector<DofLimit>::const_iterator{};
      if (!limits || dof == limits->dofs.end()) {
        throw Error(std::string("the joint limits have no ") + "XYZ"[axis] + " DOF for '" +
                    spec.name + "', which the stick model's " +
                    std::string(name_of(kJointSets, set)) + " joint set moves");
      }
      const int k = spec.angles[i];
      t.axis[k] = axis;
      t.range[k] = {dof->lower, dof->upper, dof->upper - dof->lower >= 2 * kPi - 1e-9};
    }
  }
  return t;
}

// How far `angles` lie outside their ranges, and how far they are from `previous`; candidates
// are compared on the first, then the second.
std::pair<double, double> candidate_cost(const JointSpec& joint,
                                         const std::array<AngleRange, kMaxAngles>& ranges,
                                         const Angles& candidate, const Angles& previous) {
  double violation = 0.0, change = 0.0;
  for (int i = 0; i < joint.count; ++i) {
    const int k = joint.angles[i];
    violation += std::abs(wrap(candidate[k] - limit_angle(candidate[k], ranges[k])));
    change += std::abs(wrap(candidate[k] - previous[k]));
  }
  return {violation, change};
}

}  // namespace

std::string_view angle_name(int angle) {
  static constexpr std::array<std::string_view, kMaxAngles> names = {
      "neck_lateral",       "neck_flexion",       "l_shoulder_abduction", "r_shoulder_abduction",
      "l_shoulder_flexion", "r_shoulder_flexion", "l_shoulder_twist",     "r_shoulder_twist",
      "l_elbow_flexion",    "r_elbow_flexion",    "l_hip_abduction",      "r_hip_abduction",
      "l_hip_flexion",      "r_hip_flexion",      "l_knee_flexion",       "r_knee_flexion",
      "l_hip_twist",        "r_hip_twist",        "spine_lateral",        "spine_flexion",
      "spine_twist",        "l_ankle_flexion",    "r_ankle_flexion",      "l_wrist_flexion",
      "r_wrist_flexion",    "l_wrist_deviation",  "r_wrist_deviation"};
  return names.at(angle);
}

double limit_angle(double angle, const AngleRange& range) {
  if (range.full_turn) {
    return range.lo + std::fmod(std::fmod(angle - range.lo, 2 * kPi) + 2 * kPi, 2 * kPi);
  }
  for (const double a : {angle, angle - 2 * kPi, angle + 2 * kPi}) {
    if (a >= range.lo && a <= range.hi) return a;
  }
  return std::abs(wrap(angle - range.lo)) <= std::abs(wrap(angle - range.hi)) ? range.lo : range.hi;
}

int segment_parent(int segment) {
  static constexpr std::array<int, kSegmentCount> parents = {
      -1,        kPelvis, kChest,  kChest, kLUpperArm, kLForearm, kChest, kRUpperArm,
      kRForearm, kPelvis, kLThigh, kLCalf, kPelvis,    kRThigh,   kRCalf};
  return parents.at(segment);
}

std::string_view segment_name(int segment) {
  static constexpr std::array<std::string_view, kSegmentCount> names = {
      "pelvis", "chest",   "head",   "l_upperarm", "l_forearm", "l_hand", "r_upperarm", "r_forearm",
      "r_hand", "l_thigh", "l_calf", "l_foot",     "r_thigh",   "r_calf", "r_foot"};
  return names.at(segment);
}

bool is_strict_descendant(int segment, int ancestor) {
  for (int s = segment_parent(segment); s >= 0; s = segment_parent(s)) {
    if (s == ancestor) return true;
  }
  return false;
}

void BodyDimensions::validate() const {
  const std::pair<const char*, double> lengths[] = {{"torso_half", torso_half},
                                                    {"shoulder_half", shoulder_half},
                                                    {"head", head},
                                                    {"upper_arm", upper_arm},
                                                    {"forearm", forearm},
                                                    {"hand", hand},
                                                    {"thigh", thigh},
                                                    {"calf", calf},
                                                    {"foot", foot}};
  for (const auto& [name, value] : lengths) {
    if (!(value > 0.01 && value < 2.0)) {
      throw Error(std::string("body dimension '") + name +
                  "' must be a length in (0.01, 2) m, got " + std::to_string(value));
    }
  }
  struct Fraction {
    const char* name;
    const char* meaning;
    double value;
  };
  const Fraction fractions[] = {
      {"d_s", "the shoulders' height above the trunk's centre, in trunk half-lengths", d_s},
      {"d_h", "the hips' half-spacing, in shoulder half-widths", d_h},
      {"skullbase_fraction", "the skull base's place from the neck to the crown",
       skullbase_fraction}};
  for (const auto& [name, meaning, value] : fractions) {
    if (!(value >= 0.0 && value <= 1.5)) {
      throw Error(std::string("body dimension '") + name + "' (" + meaning +
                  ") must be a fraction in [0, 1.5], got " + std::to_string(value));
    }
  }
  const std::pair<const char*, double> offsets[] = {{"root_above_hips", root_above_hips},
                                                    {"root_forward", root_forward},
                                                    {"shoulder_forward", shoulder_forward},
                                                    {"hip_forward", hip_forward},
                                                    {"spine_pivot", spine_pivot}};
  for (const auto& [name, value] : offsets) {
    if (!(std::abs(value) < torso_half)) {
      throw Error(std::string("body dimension '") + name + "' must lie within the torso, got " +
                  std::to_string(value));
    }
  }
  if (!(std::abs(foot_pitch) < kPi / 2)) {
    throw Error("body dimension 'foot_pitch' must lie within (-pi/2, pi/2), got " +
                std::to_string(foot_pitch));
  }
  for (int s = 0; s < kSegmentCount; ++s) {
    if (!(centerline_offset[s].norm() < 0.25)) {
      throw Error("body dimension 'centerline_offset' of " + std::string(segment_name(s)) +
                  " must be under 0.25 m");
    }
  }
}

Eigen::Matrix3d axis_rotation(int axis, double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::Unit(axis)).toRotationMatrix();
}

StickModel::StickModel(const BodyDimensions& dims, JointSet joints,
                       const std::vector<JointLimits>& urdf_limits)
    : dims_(dims),
      joints_(joints),
      table_(std::make_shared<const AngleTable>(make_angle_table(joints, urdf_limits))) {
  dims_.validate();
}

const std::array<AngleRange, kMaxAngles>& StickModel::ranges() const {
  return table_->range;
}

std::vector<int> StickModel::chain_angles(int segment) const {
  std::vector<int> out;
  for (int s = segment; s > kPelvis; s = segment_parent(s)) {
    const JointSpec& spec = joint_specs(joints_)[s];
    out.insert(out.end(), spec.angles.begin(), spec.angles.begin() + spec.count);
  }
  return out;
}

int StickModel::joint_dofs(int segment) const {
  return joint_specs(joints_).at(segment).count;
}

int StickModel::moving_segment(int segment) const {
  while (segment > kPelvis && joint_dofs(segment) == 0) segment = segment_parent(segment);
  return segment;
}

int StickModel::twist_angle(int segment) const {
  const JointSpec& spec = joint_specs(joints_)[segment];
  return spec.count == 3 ? spec.angles[2] : -1;
}

Eigen::Vector3d StickModel::direction(int segment) const {
  switch (segment) {
    case kPelvis:
    case kChest:
    case kHead:
      return Eigen::Vector3d::UnitY();
    case kLFoot:
    case kRFoot:
      return {0, -std::sin(dims_.foot_pitch), std::cos(dims_.foot_pitch)};
    default:
      return -Eigen::Vector3d::UnitY();
  }
}

double StickModel::length(int segment) const {
  switch (segment) {
    case kPelvis:
      return dims_.torso_half + dims_.spine_pivot;
    case kChest:
      return dims_.torso_half - dims_.spine_pivot;
    case kHead:
      return dims_.head;
    case kLUpperArm:
    case kRUpperArm:
      return dims_.upper_arm;
    case kLForearm:
    case kRForearm:
      return dims_.forearm;
    case kLHand:
    case kRHand:
      return dims_.hand;
    case kLThigh:
    case kRThigh:
      return dims_.thigh;
    case kLCalf:
    case kRCalf:
      return dims_.calf;
    default:
      return dims_.foot;
  }
}

Eigen::Vector3d StickModel::attachment(int segment) const {
  const double h = dims_.torso_half, w = dims_.shoulder_half, pivot = dims_.spine_pivot;
  switch (segment) {
    case kPelvis:
      return Eigen::Vector3d::Zero();
    case kChest:
      return {0, pivot, 0};
    case kHead:
      return {0, h - pivot, 0};
    case kLUpperArm:
      return {w, dims_.d_s * h - pivot, dims_.shoulder_forward};
    case kRUpperArm:
      return {-w, dims_.d_s * h - pivot, dims_.shoulder_forward};
    case kLThigh:
      return {dims_.d_h * w, -h, dims_.hip_forward};
    case kRThigh:
      return {-dims_.d_h * w, -h, dims_.hip_forward};
    default: {  // forearms, hands, calves and feet hang from the parent's distal end
      const int parent = segment_parent(segment);
      return direction(parent) * length(parent);
    }
  }
}

StickGeometry StickModel::geometry(const StickPose& pose) const {
  StickGeometry g;
  g.rotation[kPelvis] = pose.R0;
  g.proximal[kPelvis] = pose.t0 - pose.R0.col(1) * dims_.torso_half;
  g.distal[kPelvis] = pose.t0 + pose.R0.col(1) * dims_.spine_pivot;
  for (int s = 1; s < kSegmentCount; ++s) {
    const int p = segment_parent(s);
    const Eigen::Vector3d origin = p == kPelvis ? pose.t0 : g.proximal[p];
    const Eigen::Vector3d joint = origin + g.rotation[p] * attachment(s);
    Eigen::Matrix3d R = g.rotation[p];
    const JointSpec& spec = joint_specs(joints_)[s];
    for (int i = 0; i < spec.count; ++i) {
      const int k = spec.angles[i];
      const int axis = table_->axis[k];
      g.axis[k] = R.col(axis);
      g.pivot[k] = joint;
      R = R * axis_rotation(axis, pose.theta[k]);
    }
    g.rotation[s] = R;
    g.proximal[s] = joint;
    g.distal[s] = joint + R * direction(s) * length(s);
  }
  for (int s = 0; s < kSegmentCount; ++s) {
    const Eigen::Vector3d offset = g.rotation[s] * dims_.centerline_offset[s];
    g.line_proximal[s] = g.proximal[s] + offset;
    g.line_distal[s] = g.distal[s] + offset;
  }
  return g;
}

std::array<Eigen::Vector3d, kReferencePointCount> StickModel::reference_points(
    const StickGeometry& g) const {
  return {g.proximal[kPelvis] + g.rotation[kPelvis].col(1) * dims_.torso_half,
          g.distal[kHead],
          g.distal[kChest],
          g.proximal[kLUpperArm],
          g.proximal[kRUpperArm],
          g.proximal[kLThigh],
          g.proximal[kRThigh],
          g.distal[kLUpperArm],
          g.distal[kRUpperArm],
          g.distal[kLThigh],
          g.distal[kRThigh],
          g.distal[kLHand],
          g.distal[kRHand],
          g.distal[kLCalf],
          g.distal[kRCalf]};
}

Eigen::Matrix<double, 3 * kReferencePointCount, Eigen::Dynamic> StickModel::angle_jacobian(
    const StickGeometry& g, const std::array<Eigen::Vector3d, kReferencePointCount>& p) const {
  // The segment whose motion carries each reference point (its own angles and its ancestors').
  static constexpr std::array<int, kReferencePointCount> carrier = {
      kPelvis,    kHead,   kChest,  kChest, kChest, kPelvis, kPelvis, kLUpperArm,
      kRUpperArm, kLThigh, kRThigh, kLHand, kRHand, kLCalf,  kRCalf};
  Eigen::Matrix<double, 3 * kReferencePointCount, Eigen::Dynamic> J =
      Eigen::MatrixXd::Zero(3 * kReferencePointCount, angle_count());
  for (int i = 0; i < kReferencePointCount; ++i) {
    for (int s = carrier[i]; s > kPelvis; s = segment_parent(s)) {
      const JointSpec& spec = joint_specs(joints_)[s];
      for (int d = 0; d < spec.count; ++d) {
        const int k = spec.angles[d];
        J.block<3, 1>(3 * i, k) = g.axis[k].cross(p[i] - g.pivot[k]);
      }
    }
  }
  return J;
}

namespace {

// rotation_joints() and the segment whose rotation relative to its parent each one is.
struct RotationJoint {
  const char* name;
  int segment;
};
constexpr RotationJoint kRotationJoints[] = {
    {"humanoid_root", kPelvis}, {"l_hip", kLThigh},         {"r_hip", kRThigh},
    {"l_knee", kLCalf},         {"r_knee", kRCalf},         {"l_talocrural", kLFoot},
    {"r_talocrural", kRFoot},   {"l_shoulder", kLUpperArm}, {"r_shoulder", kRUpperArm},
    {"l_elbow", kLForearm},     {"r_elbow", kRForearm},     {"l_radiocarpal", kLHand},
    {"r_radiocarpal", kRHand}};

}  // namespace

const std::vector<std::string>& rotation_joints() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const RotationJoint& j : kRotationJoints) n.emplace_back(j.name);
    return n;
  }();
  return names;
}

std::vector<Eigen::Quaterniond> StickModel::joint_rotations(const StickPose& pose) const {
  // gt/angles.csv measures rotations from the humanoid's neutral pose, whose bones do not all
  // point where the sticks' zero angles put them (the arms hang a little apart and bent): each
  // segment's frame is turned by the least rotation taking the humanoid's neutral bone onto the
  // stick's direction, so that both neutral poses read as no rotation.
  static const std::vector<Eigen::Vector3d> neutral_bones = [] {
    const Skeleton h = build_humanoid();
    std::vector<Eigen::Vector3d> bones;
    for (const RotationJoint& j : kRotationJoints) {
      const int joint = h.require(j.name);
      int child = -1;
      for (int i = 0; i < h.size() && child < 0; ++i) child = h[i].parent == joint ? i : -1;
      bones.push_back((h[child].center - h[joint].center).normalized());
    }
    return bones;
  }();
  std::array<Eigen::Matrix3d, kSegmentCount> align;
  align.fill(Eigen::Matrix3d::Identity());
  for (size_t k = 1; k < std::size(kRotationJoints); ++k) {
    const int segment = kRotationJoints[k].segment;
    align[segment] =
        Eigen::Quaterniond::FromTwoVectors(neutral_bones[k], direction(segment)).toRotationMatrix();
  }
  const StickGeometry g = geometry(pose);
  std::vector<Eigen::Quaterniond> out;
  for (const RotationJoint& j : kRotationJoints) {
    const int parent = segment_parent(j.segment);
    const Eigen::Matrix3d world = g.rotation[j.segment] * align[j.segment];
    out.emplace_back(parent < 0 ? world : (g.rotation[parent] * align[parent]).transpose() * world);
  }
  return out;
}

std::vector<Eigen::Vector3d> StickModel::he15(const StickPose& pose) const {
  const StickGeometry g = geometry(pose);
  const auto p = reference_points(g);
  const Eigen::Vector3d root =
      g.proximal[kPelvis] + pose.R0 * Eigen::Vector3d(0, dims_.root_above_hips, dims_.root_forward);
  auto along = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double f) {
    return Eigen::Vector3d(a + f * (b - a));
  };
  const Eigen::Vector3d skullbase = along(p[kNeckPoint], p[kHeadTip], dims_.skullbase_fraction);
  const Eigen::Vector3d& l_wrist = g.distal[kLForearm];
  const Eigen::Vector3d& r_wrist = g.distal[kRForearm];
  std::vector<Eigen::Vector3d> out;
  for (const std::string& name : he15_joints()) {
    if (name == "humanoid_root")
      out.push_back(root);
    else if (name == "vc7")
      out.push_back(p[kNeckPoint]);
    else if (name == "skullbase")
      out.push_back(skullbase);
    else if (name == "l_shoulder")
      out.push_back(p[kLShoulderPoint]);
    else if (name == "r_shoulder")
      out.push_back(p[kRShoulderPoint]);
    else if (name == "l_elbow")
      out.push_back(p[kLElbowPoint]);
    else if (name == "r_elbow")
      out.push_back(p[kRElbowPoint]);
    else if (name == "l_radiocarpal")
      out.push_back(l_wrist);
    else if (name == "r_radiocarpal")
      out.push_back(r_wrist);
    else if (name == "l_hip")
      out.push_back(p[kLHipPoint]);
    else if (name == "r_hip")
      out.push_back(p[kRHipPoint]);
    else if (name == "l_knee")
      out.push_back(p[kLKneePoint]);
    else if (name == "r_knee")
      out.push_back(p[kRKneePoint]);
    else if (name == "l_talocrural")
      out.push_back(p[kLAnklePoint]);
    else if (name == "r_talocrural")
      out.push_back(p[kRAnklePoint]);
    else
      throw Error("stick model: no mapping for HE15 joint '" + name + "'");
  }
  return out;
}

void StickModel::set_segment_rotation(StickPose& pose, int segment,
                                      const Eigen::Matrix3d& world_rotation) const {
  if (segment <= kPelvis || segment >= kSegmentCount) {
    throw Error("set_segment_rotation: segment must be a limb, the chest or the head");
  }
  const JointSpec& joint = joint_specs(joints_)[segment];
  if (joint.count == 0) return;
  const StickGeometry g = geometry(pose);
  const Eigen::Matrix3d rel = g.rotation[segment_parent(segment)].transpose() * world_rotation;
  const int k0 = joint.angles[0], k1 = joint.angles[1], k2 = joint.angles[2];
  // The stick's direction first (two swing solutions, Rz(a) Rx(b) (s·Y) = d), then a twist
  // about it from what remains; clamping the twist never changes where the stick points.
  std::array<Angles, 2> cand = {pose.theta, pose.theta};
  int count = 1;
  const Eigen::Vector3d dir = direction(segment);
  if (joint.count >= 2) {
    const double s = dir.y() > 0 ? 1.0 : -1.0;  // swinging joints carry sticks along ±Y
    const Eigen::Vector3d d = rel.col(1) * s;
    const double b = std::asin(std::clamp(s * d.z(), -1.0, 1.0));
    const double a =
        std::hypot(d.x(), d.y()) < 1e-9 ? pose.theta[k0] : std::atan2(-s * d.x(), s * d.y());
    cand[0][k0] = a, cand[0][k1] = b;
    cand[1][k0] = wrap(a + kPi), cand[1][k1] = wrap(kPi - b);
    count = 2;
  } else {  // hinges about X: Rx(φ) turns the stick's angle in the Y-Z plane by φ
    const Eigen::Vector3d d = rel * dir;
    if (std::hypot(d.y(), d.z()) > 1e-9) {
      cand[0][k0] = wrap(std::atan2(d.z(), d.y()) - std::atan2(dir.z(), dir.y()));
    }
  }
  if (joint.count == 3) {  // Ry(c) = (Rz(a) Rx(b))^T rel, for each swing
    for (int i = 0; i < count; ++i) {
      const Eigen::Matrix3d r =
          (axis_rotation(2, cand[i][k0]) * axis_rotation(0, cand[i][k1])).transpose() * rel;
      cand[i][k2] = std::atan2(r(0, 2), r(0, 0));
    }
  }
  const auto& ranges = this->ranges();
  const int best = count == 2 && candidate_cost(joint, ranges, cand[1], pose.theta) <
                                     candidate_cost(joint, ranges, cand[0], pose.theta)
                       ? 1
                       : 0;
  Angles& chosen = cand[best];
  for (int i = 0; i < std::min(joint.count, 2); ++i) {
    chosen[joint.angles[i]] = limit_angle(chosen[joint.angles[i]], ranges[joint.angles[i]]);
  }
  if (joint.count == 3) {  // the twist again about the clamped swing
    const Eigen::Matrix3d r =
        (axis_rotation(2, chosen[k0]) * axis_rotation(0, chosen[k1])).transpose() * rel;
    chosen[k2] = limit_angle(std::atan2(r(0, 2), r(0, 0)), ranges[k2]);
  }
  for (int i = 0; i < joint.count; ++i) pose.theta[joint.angles[i]] = chosen[joint.angles[i]];
}

}  // namespace simcap::tracker
