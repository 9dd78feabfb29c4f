#include "tracker/moschini/pose_init.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/pose.h"
#include "tracker/moschini/weop.h"

namespace simcap::tracker {
namespace {

constexpr double kPi = std::numbers::pi;

const Eigen::Vector3d& need(const NamedJoints& joints, const std::string& name,
                            const std::string& source) {
  const auto it = joints.find(name);
  if (it == joints.end()) throw Error(source + ": joint '" + name + "' is missing");
  return it->second;
}

// Columns: lateral (left), up, forward, from the hips, vc7 and shoulders.
Eigen::Matrix3d torso_frame(const NamedJoints& j, const std::string& source) {
  const Eigen::Vector3d hip_mid = 0.5 * (need(j, "l_hip", source) + need(j, "r_hip", source));
  const Eigen::Vector3d up = (need(j, "vc7", source) - hip_mid).normalized();
  Eigen::Vector3d lateral = need(j, "l_hip", source) - need(j, "r_hip", source) +
                            need(j, "l_shoulder", source) - need(j, "r_shoulder", source);
  lateral = (lateral - lateral.dot(up) * up).normalized();
  Eigen::Matrix3d R;
  R.col(0) = lateral;
  R.col(1) = up;
  R.col(2) = lateral.cross(up);
  if (!R.allFinite()) throw Error(source + ": the torso joints are degenerate");
  return R;
}

// Ratios of the neutral humanoid for what the HE15 set lacks.
struct NeutralRatios {
  double skullbase_fraction;  // along vc7 -> skull_tip
  double hand_per_forearm;    // |hand_tip - wrist| / |wrist - elbow|
  double root_above_hips;     // per unit torso length (hip midpoint to vc7)
  double spine_pivot;         // vl1 above the torso centroid, per unit torso length
  double foot_per_calf;       // |metatarsophalangeal_2 - talocrural| / |talocrural - knee|
  double foot_pitch;          // the ball of the foot below the ankle's level, radians
};
const NeutralRatios& neutral_ratios() {
  static const NeutralRatios r = [] {
    const Skeleton s = build_humanoid();
    const auto p = joint_positions(s, Pose::neutral(s));
    auto at = [&](const char* n) { return p[s.require(n)]; };
    const Eigen::Vector3d hip_mid = 0.5 * (at("l_hip") + at("r_hip"));
    const double torso = (at("vc7") - hip_mid).norm();
    const Eigen::Vector3d foot = at("l_metatarsophalangeal_2") - at("l_talocrural");
    return NeutralRatios{
        (at("skullbase") - at("vc7")).norm() / (at("skull_tip") - at("vc7")).norm(),
        (at("l_hand_tip") - at("l_radiocarpal")).norm() /
            (at("l_radiocarpal") - at("l_elbow")).norm(),
        (at("humanoid_root") - hip_mid).y() / torso,
        (at("vl1").y() - 0.5 * (hip_mid.y() + at("vc7").y())) / torso,
        foot.norm() / (at("l_talocrural") - at("l_knee")).norm(),
        std::atan2(-foot.y(), foot.z())};
  }();
  return r;
}

void point_segment(const StickModel& model, StickPose& pose, int segment,
                   const Eigen::Vector3d& target) {
  if (!(target.norm() > 1e-9)) return;
  const Eigen::Matrix3d R = model.geometry(pose).rotation[segment];
  const Eigen::Vector3d current = R * model.direction(segment);
  const Eigen::Matrix3d turn =
      Eigen::Quaterniond::FromTwoVectors(current, target.normalized()).toRotationMatrix();
  model.set_segment_rotation(pose, segment, turn * R);
}

// Frame of an upper limb whose -Y is the limb and whose hinge (X) bends the next limb towards
// +Z (elbows, bend = +1) or -Z (knees, bend = -1); a straight limb keeps the torso's forward.
Eigen::Matrix3d limb_frame(const Eigen::Vector3d& limb, const Eigen::Vector3d& next,
                           const Eigen::Vector3d& forward, double bend) {
  const Eigen::Vector3d y = -limb.normalized();
  Eigen::Vector3d z = bend * (next - next.dot(y) * y);
  if (z.norm() < 0.05 * next.norm()) z = forward - forward.dot(y) * y;
  z.normalize();
  Eigen::Matrix3d R;
  R.col(0) = y.cross(z);
  R.col(1) = y;
  R.col(2) = z;
  return R;
}

}  // namespace

NamedJoints joints_at(const JointTrack& track, int frame, const std::string& source) {
  const auto it = std::find(track.frames.begin(), track.frames.end(), frame);
  if (it == track.frames.end()) {
    throw Error(source + ": no ground truth for frame " + std::to_string(frame));
  }
  const auto& row = track.positions[it - track.frames.begin()];
  NamedJoints out;
  for (size_t j = 0; j < track.joints.size(); ++j) {
    if (row[j].allFinite()) out[track.joints[j]] = row[j];
  }
  return out;
}

BodyDimensions dimensions_from_joints(const NamedJoints& j, const std::string& source) {
  auto at = [&](const std::string& n) { return need(j, n, source); };
  auto dist = [&](const std::string& a, const std::string& b) { return (at(a) - at(b)).norm(); };
  const NeutralRatios& ratio = neutral_ratios();
  const Eigen::Matrix3d R = torso_frame(j, source);
  const Eigen::Vector3d hip_mid = 0.5 * (at("l_hip") + at("r_hip"));
  const Eigen::Vector3d centroid = 0.5 * (hip_mid + at("vc7"));
  BodyDimensions d;
  d.torso_half = 0.5 * (at("vc7") - hip_mid).norm();
  const Eigen::Vector3d ls = R.transpose() * (at("l_shoulder") - centroid);
  const Eigen::Vector3d rs = R.transpose() * (at("r_shoulder") - centroid);
  const Eigen::Vector3d lh = R.transpose() * (at("l_hip") - centroid);
  const Eigen::Vector3d rh = R.transpose() * (at("r_hip") - centroid);
  d.shoulder_half = 0.5 * (ls.x() - rs.x());
  d.d_s = 0.5 * (ls.y() + rs.y()) / d.torso_half;
  d.d_h = 0.5 * (lh.x() - rh.x()) / d.shoulder_half;
  d.shoulder_forward = 0.5 * (ls.z() + rs.z());
  d.hip_forward = 0.5 * (lh.z() + rh.z());
  d.root_above_hips = j.count("humanoid_root") ? (at("humanoid_root") - hip_mid).dot(R.col(1))
                                               : ratio.root_above_hips * 2 * d.torso_half;
  d.root_forward = j.count("humanoid_root") ? (at("humanoid_root") - hip_mid).dot(R.col(2)) : 0.0;
  d.spine_pivot =
      j.count("vl1") ? (at("vl1") - centroid).dot(R.col(1)) : ratio.spine_pivot * 2 * d.torso_half;
  if (j.count("skull_tip")) {
    d.head = dist("skull_tip", "vc7");
    d.skullbase_fraction = dist("skullbase", "vc7") / d.head;
  } else {
    d.skullbase_fraction = ratio.skullbase_fraction;
    d.head = dist("skullbase", "vc7") / d.skullbase_fraction;
  }
  d.upper_arm = 0.5 * (dist("l_elbow", "l_shoulder") + dist("r_elbow", "r_shoulder"));
  d.forearm = 0.5 * (dist("l_radiocarpal", "l_elbow") + dist("r_radiocarpal", "r_elbow"));
  d.hand = j.count("l_hand_tip") && j.count("r_hand_tip")
               ? 0.5 * (dist("l_hand_tip", "l_radiocarpal") + dist("r_hand_tip", "r_radiocarpal"))
               : d.forearm * ratio.hand_per_forearm;
  d.thigh = 0.5 * (dist("l_knee", "l_hip") + dist("r_knee", "r_hip"));
  d.calf = 0.5 * (dist("l_talocrural", "l_knee") + dist("r_talocrural", "r_knee"));
  d.foot = j.count("l_metatarsophalangeal_2") && j.count("r_metatarsophalangeal_2")
               ? 0.5 * (dist("l_metatarsophalangeal_2", "l_talocrural") +
                        dist("r_metatarsophalangeal_2", "r_talocrural"))
               : ratio.foot_per_calf * d.calf;
  d.foot_pitch = ratio.foot_pitch;
  try {
    d.validate();
  } catch (const Error& e) {
    throw Error(source + ": the body there is one Moschini's stick model cannot hold: " + e.what());
  }
  return d;
}

StickPose pose_from_joints(const StickModel& model, const NamedJoints& j,
                           const std::string& source) {
  auto at = [&](const std::string& n) { return need(j, n, source); };
  const BodyDimensions& d = model.dimensions();
  // The trunk's joints where the model has them in its rest pose (root at the origin, unturned).
  const StickGeometry rest = model.geometry(StickPose{});
  const std::vector<std::pair<std::string, Eigen::Vector3d>> pelvis = {
      {"humanoid_root",
       rest.proximal[kPelvis] + Eigen::Vector3d(0, d.root_above_hips, d.root_forward)},
      {"l_hip", rest.proximal[kLThigh]},
      {"r_hip", rest.proximal[kRThigh]}};
  const std::vector<std::pair<std::string, Eigen::Vector3d>> chest = {
      {"vc7", rest.distal[kChest]},
      {"l_shoulder", rest.proximal[kLUpperArm]},
      {"r_shoulder", rest.proximal[kRUpperArm]}};
  auto columns = [&](const auto& named, const Eigen::Vector3d& origin, Eigen::Matrix3Xd& model_pts,
                     Eigen::Matrix3Xd& data_pts) {
    const Eigen::Index n = model_pts.cols();
    model_pts.conservativeResize(3, n + static_cast<Eigen::Index>(named.size()));
    data_pts.conservativeResize(3, model_pts.cols());
    for (size_t i = 0; i < named.size(); ++i) {
      model_pts.col(n + i) = named[i].second;
      data_pts.col(n + i) = at(named[i].first) - origin;
    }
  };
  // The pelvis is the rigid motion that best maps its joints onto the data (and the chest's
  // too when the spine has no joint); then the chest turns about the spine joint.
  const bool spine = model.joint_dofs(kChest) > 0;
  Eigen::Matrix3Xd A(3, 0), B(3, 0);
  columns(pelvis, Eigen::Vector3d::Zero(), A, B);
  if (!spine) columns(chest, Eigen::Vector3d::Zero(), A, B);
  const RigidMotion trunk = weop(A, B, Eigen::VectorXd::Ones(A.cols()));
  StickPose pose;
  pose.R0 = trunk.R;
  pose.t0 = trunk.t;
  pose.theta.fill(0.0);
  if (spine) {
    const StickGeometry g = model.geometry(pose);
    const Eigen::Vector3d pivot = g.proximal[kChest];
    Eigen::Matrix3Xd a(3, 0), b(3, 0);
    columns(chest, pivot, a, b);
    for (Eigen::Index i = 0; i < a.cols(); ++i) {
      a.col(i) = pose.R0 * a.col(i) + pose.t0 - pivot;
    }
    model.set_segment_rotation(pose, kChest, wopp(a, b, Eigen::VectorXd::Ones(a.cols())) * pose.R0);
  }
  point_segment(model, pose, kHead,
                (j.count("skull_tip") ? at("skull_tip") : at("skullbase")) - at("vc7"));
  const StickGeometry trunk_pose = model.geometry(pose);
  const Eigen::Vector3d chest_forward = trunk_pose.rotation[kChest].col(2);
  for (const auto& [side, upper, fore, hand] :
       {std::tuple{std::string("l_"), kLUpperArm, kLForearm, kLHand},
        std::tuple{std::string("r_"), kRUpperArm, kRForearm, kRHand}}) {
    const Eigen::Vector3d arm = at(side + "elbow") - at(side + "shoulder");
    const Eigen::Vector3d forearm = at(side + "radiocarpal") - at(side + "elbow");
    model.set_segment_rotation(pose, upper, limb_frame(arm, forearm, chest_forward, 1.0));
    point_segment(model, pose, fore, forearm);
    const std::string tip = side + "hand_tip";
    if (j.count(tip)) point_segment(model, pose, hand, at(tip) - at(side + "radiocarpal"));
  }
  const Eigen::Vector3d pelvis_forward = pose.R0.col(2);
  for (const auto& [side, thigh, calf, foot] :
       {std::tuple{std::string("l_"), kLThigh, kLCalf, kLFoot},
        std::tuple{std::string("r_"), kRThigh, kRCalf, kRFoot}}) {
    const Eigen::Vector3d femur = at(side + "knee") - at(side + "hip");
    const Eigen::Vector3d tibia = at(side + "talocrural") - at(side + "knee");
    model.set_segment_rotation(pose, thigh, limb_frame(femur, tibia, pelvis_forward, -1.0));
    point_segment(model, pose, calf, tibia);
    const std::string ball = side + "metatarsophalangeal_2";
    if (j.count(ball)) point_segment(model, pose, foot, at(ball) - at(side + "talocrural"));
  }
  return pose;
}

std::array<Eigen::Vector3d, kSegmentCount> measure_centerline_offsets(
    const StickModel& model, const StickPose& pose, const std::vector<Eigen::Vector3d>& points) {
  const StickGeometry g = model.geometry(pose);
  std::array<std::vector<double>, 2> across[kHead + 1];  // [pelvis, chest, head][x, z]
  for (const Eigen::Vector3d& x : points) {
    int best = -1;
    double best_d = 0.15, best_t = 0;  // farther points are not this stick's
    for (int s = 0; s < kSegmentCount; ++s) {
      const Eigen::Vector3d ab = g.distal[s] - g.proximal[s];
      const double t = std::clamp((x - g.proximal[s]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      const double d = (x - g.proximal[s] - t * ab).norm();
      if (d < best_d) best = s, best_d = d, best_t = t;
    }
    // Only the middle of a stick: its ends mix with the neighbouring segments.
    if ((!is_trunk(best) && best != kHead) || best_t < 0.15 || best_t > 0.85) continue;
    const Eigen::Vector3d ab = g.distal[best] - g.proximal[best];
    const Eigen::Vector3d r = g.rotation[best].transpose() * (x - g.proximal[best] - best_t * ab);
    across[best][0].push_back(r.x());
    across[best][1].push_back(r.z());
  }
  std::array<Eigen::Vector3d, kSegmentCount> offsets = no_offsets();
  for (int s : {kPelvis, kChest, kHead}) {
    if (across[s][0].size() < 5) continue;
    for (int a = 0; a < 2; ++a) {
      auto& v = across[s][a];
      std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
      offsets[s][a == 0 ? 0 : 2] = v[v.size() / 2];
    }
  }
  return offsets;
}

namespace {

// simcap's humanoid of `height_m` standing in its neutral pose on the floor y = 0.
NamedJoints neutral_humanoid(double height_m) {
  BodyParameters body;
  body.height = height_m;
  const Skeleton s = build_humanoid(body);
  const auto p = joint_positions(s, Pose::neutral(s));
  NamedJoints joints;
  for (int i = 0; i < s.size(); ++i) joints[s[i].name] = p[i];
  return joints;
}

}  // namespace

BodyDimensions dimensions_from_height(double height_m) {
  return dimensions_from_joints(neutral_humanoid(height_m),
                                "humanoid of height " + std::to_string(height_m));
}

double ankle_height_from_height(double height_m) {
  const NamedJoints joints = neutral_humanoid(height_m);
  return 0.5 * (joints.at("l_talocrural").y() + joints.at("r_talocrural").y());
}

UprightCue upright_cue(const Occupancy& hull, const BodyDimensions& dims) {
  UprightCue cue;
  if (hull.count == 0) return cue;
  const VoxelGrid& g = hull.grid;
  int top = -1;
  for (int y = hull.size.y() - 1; y >= 0 && top < 0; --y) {
    for (size_t i = 0; i < static_cast<size_t>(hull.size.x()) * hull.size.z(); ++i) {
      if (hull.cells[static_cast<size_t>(y) * hull.size.x() * hull.size.z() + i]) {
        top = y;
        break;
      }
    }
  }
  cue.top_y = g.origin.y() + g.voxel * (hull.lo.y() + top);
  // The horizontal centroid of the torso's height band.
  const double centroid_y = cue.top_y - dims.head - dims.torso_half;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  int count = 0;
  for (int y = 0; y < hull.size.y(); ++y) {
    const double wy = g.origin.y() + g.voxel * (hull.lo.y() + y);
    if (std::abs(wy - centroid_y) > 0.5 * dims.torso_half) continue;
    for (int z = 0; z < hull.size.z(); ++z) {
      for (int x = 0; x < hull.size.x(); ++x) {
        if (!hull.cells[(static_cast<size_t>(y) * hull.size.z() + z) * hull.size.x() + x]) continue;
        sum += Eigen::Vector2d(g.origin.x() + g.voxel * (hull.lo.x() + x),
                               g.origin.z() + g.voxel * (hull.lo.z() + z));
        ++count;
      }
    }
  }
  if (count > 0) cue.torso_xz = sum / count;
  return cue;
}

std::vector<StickPose> upright_hypotheses(const StickModel& model, const UprightCue& cue,
                                          int headings) {
  const BodyDimensions& d = model.dimensions();
  std::vector<StickPose> out;
  for (int k = 0; k < std::max(1, headings); ++k) {
    // Facing +Z at yaw 0; yaw ψ faces (sin ψ, cos ψ) in (x, z).
    const double yaw = 2 * kPi * k / std::max(1, headings);
    StickPose p;
    p.R0 = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix();
    p.t0 = Eigen::Vector3d(cue.torso_xz.x(), cue.top_y - d.head - d.torso_half, cue.torso_xz.y());
    p.theta.fill(0.0);
    p.theta[kLShoulder1] = 0.15;
    p.theta[kRShoulder1] = -0.15;
    p.theta[kLElbow] = p.theta[kRElbow] = -0.2;
    out.push_back(p);
  }
  return out;
}

}  // namespace simcap::tracker
