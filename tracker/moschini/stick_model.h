// Moschini's stick-figure body (§4.1, §5.1.2): rigid sticks on a pelvis root with his 16 joint
// angles (Table 5.1), its 15 reference points (Table 5.2) and the HE15 joints read off them.
// simcap's URDF joint set adds a spine joint between pelvis and chest, wrists and ankles.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/name_table.h"
#include "models/joint_limits.h"

namespace simcap::tracker {

// Joint angles, stored 0-based: Moschini's θ1..θ16 (Table 5.1) and, for the URDF joint set,
// the hip twists, the spine, the ankles and the wrists after them. They are the degrees of
// freedom of models/joint_limits.h: angles about the axes of the parent segment's frame, which
// is world-aligned in simcap's neutral pose (upright, arms hanging, X left, Y up, Z forward),
// R = Rz(a) Rx(b) Ry(c) for the DOFs a joint has. Signs are right-handed on both sides, so an
// abduction or twist has opposite signs left and right.
enum JointAngle : int {
  kNeck1,       // θ1  vc7 lateral bend (Z)
  kNeck2,       // θ2  vc7 flexion (X, positive = chin forward)
  kLShoulder1,  // θ3  shoulder abduction (Z)
  kRShoulder1,  // θ4
  kLShoulder2,  // θ5  shoulder flexion (X, negative = arm forward)
  kRShoulder2,  // θ6
  kLShoulder3,  // θ7  twist about the upper arm (Y)
  kRShoulder3,  // θ8
  kLElbow,      // θ9  flexion (X, negative)
  kRElbow,      // θ10
  kLHip1,       // θ11 abduction (Z)
  kRHip1,       // θ12
  kLHip2,       // θ13 flexion (X, negative = thigh forward)
  kRHip2,       // θ14
  kLKnee,       // θ15 flexion (X, positive)
  kRKnee,       // θ16
  kLHipTwist,   // URDF set only: twist about the thigh (Y)
  kRHipTwist,
  kSpineLateral,  // URDF set only: the thoracolumbar spine as one joint, lateral bend (Z)
  kSpineFlexion,  //   flexion (X, positive = chest forward)
  kSpineTwist,    //   twist (Y)
  kLAnkle,        // URDF set only: ankle flexion (X, positive = toes down)
  kRAnkle,
  kLWristFlexion,  // URDF set only: wrist flexion (Z, towards the palm: negative on the left)
  kRWristFlexion,
  kLWristDeviation,  //   radial / ulnar deviation (X, towards the thumb: negative)
  kRWristDeviation,
  kMaxAngles
};
inline constexpr int kMoschiniAngles = 16;
using Angles = std::array<double, kMaxAngles>;

// Which degrees of freedom the sticks' joints have.
enum class JointSet {
  // Moschini's 16 angles with Table 5.1's ranges (the EKF state has his 23 parameters): pelvis
  // and chest are one rigid torso and the feet are fixed to the calves. His hips cannot turn
  // about the thigh, so the knee's hinge axis cannot follow a toe-out.
  moschini,
  // The URDF's DOFs and ranges (models/joint_limits.h humanoid_joint_limits()): the hips gain
  // their twist, the chest turns on the pelvis about one spine joint (the thoracolumbar joints
  // lumped, their ranges summed), the feet flex at the ankles and the hands swing at the wrists
  // (34 EKF parameters). The neck keeps two DOFs and the wrists lose their twist: a single
  // stick cannot show its own.
  urdf,
};
inline constexpr NameTable<JointSet, 2> kJointSets{
    {{"moschini", JointSet::moschini}, {"urdf", JointSet::urdf}}};

struct AngleRange {
  double lo = 0.0;
  double hi = 0.0;
  bool full_turn = false;  // the range is a whole circle: angles wrap instead of clamping
};

std::string_view angle_name(int angle);
// The angle moved into its range: wrapped for full turns, else the nearer bound (on the circle).
double limit_angle(double angle, const AngleRange& range);

// The sticks in pre-order (every parent before its children). Moschini's torso is the pelvis
// and the chest: the pelvis runs from the hip line up to the spine joint, the chest on to vc7.
// His forearm sticks reach the finger tips: here a forearm and a hand.
enum Segment : int {
  kPelvis,
  kChest,
  kHead,
  kLUpperArm,
  kLForearm,
  kLHand,
  kRUpperArm,
  kRForearm,
  kRHand,
  kLThigh,
  kLCalf,
  kLFoot,
  kRThigh,
  kRCalf,
  kRFoot,
  kSegmentCount
};
int segment_parent(int segment);  // -1 for the pelvis
// The pelvis and the chest: the trunk.
inline bool is_trunk(int segment) {
  return segment == kPelvis || segment == kChest;
}
std::string_view segment_name(int segment);
// True when `segment` lies strictly below `ancestor` in the tree.
bool is_strict_descendant(int segment, int ancestor);

// The 15 reference points of Table 5.2 (p1..p15, stored 0-based).
enum ReferencePoint : int {
  kTorsoCentroid,
  kHeadTip,
  kNeckPoint,
  kLShoulderPoint,
  kRShoulderPoint,
  kLHipPoint,
  kRHipPoint,
  kLElbowPoint,
  kRElbowPoint,
  kLKneePoint,
  kRKneePoint,
  kLHandTip,
  kRHandTip,
  kLAnklePoint,  // Moschini's "foot": the calf's end
  kRAnklePoint,
  kReferencePointCount
};

inline std::array<Eigen::Vector3d, kSegmentCount> no_offsets() {
  std::array<Eigen::Vector3d, kSegmentCount> a;
  a.fill(Eigen::Vector3d::Zero());
  return a;
}

// Stick lengths and the torso's shape (Table 5.3 with full lengths instead of its "2λ"). The
// torso runs from the hip line (hip midpoint) to the neck (vc7) through its centroid, where the
// root's frame is; the spine joint lies on that axis.
struct BodyDimensions {
  double torso_half = 0.26;     // λ0(2): centroid to neck, and centroid to the hip line
  double spine_pivot = -0.08;   // height of the spine joint above the centroid (below: < 0)
  double shoulder_half = 0.18;  // λ0(1): torso axis to each shoulder centre
  double d_s = 0.8;             // shoulder height above the centroid, fraction of torso_half
  double d_h = 0.7;             // hip half-spacing, fraction of shoulder_half
  // Depth of the shoulder and hip centres in front of the torso axis (Table 5.3 puts them on
  // it; mocap subjects carry the shoulders forward of C7).
  double shoulder_forward = 0.0;
  double hip_forward = 0.0;
  double head = 0.31;       // neck (vc7) to head tip
  double upper_arm = 0.33;  // shoulder to elbow
  double forearm = 0.26;    // elbow to wrist (radiocarpal)
  double hand = 0.19;       // wrist to hand tip
  double thigh = 0.43;      // hip to knee
  double calf = 0.43;       // knee to ankle
  double foot = 0.14;       // ankle to the ball of the foot (metatarsophalangeal_2)
  double foot_pitch = 0.5;  // how far the ball lies below the ankle's level, radians, ankle at 0
  // HE15 points that are not stick ends (see StickModel::he15).
  double root_above_hips = 0.06;     // humanoid_root above the hip line, along the torso axis
  double root_forward = 0.0;         // ...and in front of it
  double skullbase_fraction = 0.47;  // skullbase along the head stick from the neck
  // Where the hull's centerline runs relative to each stick's joint line, in the segment's
  // frame: the spine's joints lie near the back of the torso, so the centroids of torso slices
  // run in front of them. ICP matches points to the offset lines; joints stay on the joint line.
  std::array<Eigen::Vector3d, kSegmentCount> centerline_offset = no_offsets();

  // Throws Error naming the first dimension that is not a positive length / valid fraction.
  void validate() const;
};

struct StickPose {
  Eigen::Vector3d t0 = Eigen::Vector3d::Zero();      // torso centroid, world
  Eigen::Matrix3d R0 = Eigen::Matrix3d::Identity();  // pelvis frame -> world
  Angles theta{};
};

// The world placement of every stick for one pose.
struct StickGeometry {
  std::array<Eigen::Matrix3d, kSegmentCount> rotation;  // segment frame -> world
  std::array<Eigen::Vector3d, kSegmentCount> proximal;  // joint end (hip line for the pelvis)
  std::array<Eigen::Vector3d, kSegmentCount> distal;
  // The lines ICP matches points to: the joint line shifted by the centerline offset.
  std::array<Eigen::Vector3d, kSegmentCount> line_proximal;
  std::array<Eigen::Vector3d, kSegmentCount> line_distal;
  // World axis and pivot of every angle's rotation (for Jacobians).
  std::array<Eigen::Vector3d, kMaxAngles> axis;
  std::array<Eigen::Vector3d, kMaxAngles> pivot;
};

// Each angle's axis (0 = X, 1 = Y, 2 = Z) and range.
struct AngleTable {
  std::array<int, kMaxAngles> axis{};
  std::array<AngleRange, kMaxAngles> range{};
};

class StickModel {
 public:
  // The urdf joint set takes its ranges from `urdf_limits` (read_urdf_limits of a user's file,
  // by default the shipped humanoid_limits.urdf); the moschini set from Table 5.1. Throws Error
  // when the limits lack a DOF the joint set moves.
  StickModel(const BodyDimensions& dims, JointSet joints,
             const std::vector<JointLimits>& urdf_limits = humanoid_joint_limits());
  const BodyDimensions& dimensions() const { return dims_; }
  JointSet joint_set() const { return joints_; }
  int angle_count() const { return joints_ == JointSet::moschini ? kMoschiniAngles : kMaxAngles; }
  // Table 5.1's ranges (moschini) or the URDF's (urdf), indexed by JointAngle.
  const std::array<AngleRange, kMaxAngles>& ranges() const;

  StickGeometry geometry(const StickPose& pose) const;
  std::array<Eigen::Vector3d, kReferencePointCount> reference_points(const StickGeometry& g) const;
  // d(reference point i)/d(θk) as rows 3i..3i+2, column k < angle_count(); zero where θk does
  // not move point i.
  Eigen::Matrix<double, 3 * kReferencePointCount, Eigen::Dynamic> angle_jacobian(
      const StickGeometry& g, const std::array<Eigen::Vector3d, kReferencePointCount>& p) const;

  // HE15 joints in he15_joints() order. humanoid_root sits root_above_hips above the hip line
  // and root_forward in front of it (the torso centroid is not the pelvis); vc7 is the neck;
  // skullbase lies on the head stick at its fraction; radiocarpal is the forearm's end and
  // talocrural the calf's (Moschini's "foot").
  std::vector<Eigen::Vector3d> he15(const StickPose& pose) const;

  // The rotations of the H-Anim joints in rotation_joints(), as gt/angles.csv has them: each
  // relative to the neutral pose, in its parent's frame. The pelvis gives humanoid_root; the
  // clavicles are fixed to the chest, so a shoulder's rotation is the upper arm's relative to
  // the chest. The spine and neck, which the sticks lump into one joint each, are left out.
  std::vector<Eigen::Quaterniond> joint_rotations(const StickPose& pose) const;

  // Moves the angles of `segment` (not the pelvis) so that its world rotation comes as close to
  // `world_rotation` as its joint allows, given its parent's current placement: three angles
  // for a shoulder, the spine or a URDF hip, the stick direction for the 2-angle neck and hips
  // and the 1-angle elbows, knees and ankles; nothing for a joint without DOFs. The result
  // respects the joint limits.
  void set_segment_rotation(StickPose& pose, int segment,
                            const Eigen::Matrix3d& world_rotation) const;

  // The angles that move `segment`: its joint's and its ancestors' (at most seven).
  std::vector<int> chain_angles(int segment) const;
  // How many angles the joint of `segment` has (0 for the pelvis and for fixed joints).
  int joint_dofs(int segment) const;
  // The segment that moves `segment` rigidly: itself, or its nearest ancestor whose joint has
  // angles (the pelvis for a chest without a spine joint).
  int moving_segment(int segment) const;

  // The angle that twists `segment` about its own stick (the innermost Y rotation of a 3-DOF
  // joint), or -1 when its joint has none.
  int twist_angle(int segment) const;

  // Unit direction of a stick in its own frame (+Y up the trunk and head, -Y down the limbs,
  // forward and down along a foot) and its length.
  Eigen::Vector3d direction(int segment) const;
  double length(int segment) const;
  // Where a segment's proximal joint sits in its parent's frame, relative to the parent's
  // origin (the torso centroid for the pelvis, else the parent's proximal joint).
  Eigen::Vector3d attachment(int segment) const;

 private:
  BodyDimensions dims_;
  JointSet joints_;
  std::shared_ptr<const AngleTable> table_;  // shared by copies of the model
};

// The joints of StickModel::joint_rotations(), in its order.
const std::vector<std::string>& rotation_joints();

// Rotation by `angle` about a coordinate axis (0 = X, 1 = Y, 2 = Z).
Eigen::Matrix3d axis_rotation(int axis, double angle);

}  // namespace simcap::tracker
