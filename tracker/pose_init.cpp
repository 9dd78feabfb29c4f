#include "tracker/pose_init.h"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"
#include "models/humanoid.h"
#include "models/pose.h"

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

// Ratios of the neutral humanoid for sticks whose far end the HE15 set lacks.
struct NeutralRatios {
  double skullbase_fraction;  // along vc7 -> skull_tip
  double hand_per_forearm;    // |hand_tip - wrist| / |wrist - elbow|
  double root_above_hips;     // per unit torso length (hip midpoint to vc7)
};
const NeutralRatios& neutral_ratios() {
  static const NeutralRatios r = [] {
    const Skeleton s = build_humanoid();
    const auto p = joint_positions(s, Pose::neutral(s));
    auto at = [&](const char* n) { return p[s.require(n)]; };
    const Eigen::Vector3d hip_mid = 0.5 * (at("l_hip") + at("r_hip"));
    return NeutralRatios{
        (at("skullbase") - at("vc7")).norm() / (at("skull_tip") - at("vc7")).norm(),
        (at("l_hand_tip") - at("l_radiocarpal")).norm() /
            (at("l_radiocarpal") - at("l_elbow")).norm(),
        (at("humanoid_root") - hip_mid).y() / (at("vc7") - hip_mid).norm()};
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
  if (j.count("skull_tip")) {
    d.head = dist("skull_tip", "vc7");
    d.skullbase_fraction = dist("skullbase", "vc7") / d.head;
  } else {
    d.skullbase_fraction = ratio.skullbase_fraction;
    d.head = dist("skullbase", "vc7") / d.skullbase_fraction;
  }
  d.upper_arm = 0.5 * (dist("l_elbow", "l_shoulder") + dist("r_elbow", "r_shoulder"));
  const double forearm =
      0.5 * (dist("l_radiocarpal", "l_elbow") + dist("r_radiocarpal", "r_elbow"));
  const double hand =
      j.count("l_hand_tip") && j.count("r_hand_tip")
          ? 0.5 * (dist("l_hand_tip", "l_radiocarpal") + dist("r_hand_tip", "r_radiocarpal"))
          : forearm * ratio.hand_per_forearm;
  d.forearm = forearm + hand;
  d.wrist_fraction = forearm / d.forearm;
  d.thigh = 0.5 * (dist("l_knee", "l_hip") + dist("r_knee", "r_hip"));
  d.calf = 0.5 * (dist("l_talocrural", "l_knee") + dist("r_talocrural", "r_knee"));
  try {
    d.validate();
  } catch (const Error& e) {
    throw Error(source + ": " + e.what());
  }
  return d;
}

StickPose pose_from_joints(const StickModel& model, const NamedJoints& j,
                           const std::string& source) {
  auto at = [&](const std::string& n) { return need(j, n, source); };
  StickPose pose;
  pose.R0 = torso_frame(j, source);
  pose.t0 = 0.5 * (0.5 * (at("l_hip") + at("r_hip")) + at("vc7"));
  pose.theta.fill(0.0);
  point_segment(model, pose, kHead,
                (j.count("skull_tip") ? at("skull_tip") : at("skullbase")) - at("vc7"));
  const Eigen::Vector3d forward = pose.R0.col(2);
  for (const auto& [side, upper, fore] : {std::tuple{std::string("l_"), kLUpperArm, kLForearm},
                                          std::tuple{std::string("r_"), kRUpperArm, kRForearm}}) {
    const Eigen::Vector3d arm = at(side + "elbow") - at(side + "shoulder");
    const Eigen::Vector3d forearm = at(side + "radiocarpal") - at(side + "elbow");
    model.set_segment_rotation(pose, upper, limb_frame(arm, forearm, forward, 1.0));
    point_segment(model, pose, fore, forearm);
  }
  for (const auto& [side, thigh, calf] : {std::tuple{std::string("l_"), kLThigh, kLCalf},
                                          std::tuple{std::string("r_"), kRThigh, kRCalf}}) {
    const Eigen::Vector3d femur = at(side + "knee") - at(side + "hip");
    const Eigen::Vector3d tibia = at(side + "talocrural") - at(side + "knee");
    model.set_segment_rotation(pose, thigh, limb_frame(femur, tibia, forward, -1.0));
    point_segment(model, pose, calf, tibia);
  }
  return pose;
}

std::array<Eigen::Vector3d, kSegmentCount> measure_centerline_offsets(
    const StickModel& model, const StickPose& pose, const std::vector<Eigen::Vector3d>& points) {
  const StickGeometry g = model.geometry(pose);
  std::array<std::vector<double>, 2> across[2];  // [torso, head][x, z]
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
    if ((best != kTorso && best != kHead) || best_t < 0.15 || best_t > 0.85) continue;
    const Eigen::Vector3d ab = g.distal[best] - g.proximal[best];
    const Eigen::Vector3d r = g.rotation[best].transpose() * (x - g.proximal[best] - best_t * ab);
    across[best][0].push_back(r.x());
    across[best][1].push_back(r.z());
  }
  std::array<Eigen::Vector3d, kSegmentCount> offsets = no_offsets();
  for (int s : {kTorso, kHead}) {
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

// One pass of measure_radii: every ray goes to the part it passes most inside of, given the
// radii so far (nearest axis alone would hand the torso's edge rays to an arm hanging beside it).
void measure_radii_once(BodyDimensions& dims, const BodyDimensions& typical, const StickGeometry& g,
                        const std::vector<SilhouetteRay>& rays) {
  // A ray that meets a cylinder of radius r passes its axis at a distance uniform in [0, r] (the
  // silhouette pixels are a uniform grid), so r is twice the median: the median shrugs off the
  // rays that belong to another part yet pass this one more inside.
  constexpr int kBins = 6;  // directions across the torso axis, folded into a quarter turn
  std::array<std::vector<double>, kSegmentCount> d;
  std::array<std::vector<double>, kBins> torso;
  const double torso_reach = std::max(dims.radius[kTorso], dims.torso_width);
  for (const SilhouetteRay& ray : rays) {
    int best = -1;
    double best_inside = std::numeric_limits<double>::infinity(), best_d = 0, best_t = 0;
    Eigen::Vector3d across = Eigen::Vector3d::Zero();
    for (int s = 0; s < kSegmentCount; ++s) {
      const Eigen::Vector3d ab = g.line_distal[s] - g.line_proximal[s];
      const Eigen::Vector3d q = nearest_on_ray(ray, g.line_proximal[s], g.line_distal[s]);
      const double t = std::clamp((q - g.line_proximal[s]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      const Eigen::Vector3d r = q - g.line_proximal[s] - t * ab;
      const double inside = r.norm() - (s == kTorso ? torso_reach : dims.radius[s]);
      if (inside < best_inside)
        best = s, best_inside = inside, best_d = r.norm(), best_t = t, across = r;
    }
    if (best < 0 || best_t < 0.2 || best_t > 0.8) continue;
    d[best].push_back(best_d);
    if (best != kTorso) continue;
    const Eigen::Vector3d p = g.rotation[kTorso].transpose() * across;
    const double angle = std::atan2(std::abs(p.z()), std::abs(p.x()));
    torso[std::min(kBins - 1, static_cast<int>(angle / (std::numbers::pi / 2) * kBins))].push_back(
        best_d);
  }
  auto twice_median = [](std::vector<double>& v) {
    if (v.size() < 10) return 0.0;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return 2 * v[v.size() / 2];
  };
  // A part that few rays reach, or a pose far enough off to hand it another part's rays, keeps
  // (or stays near) its typical radius: a measurement outside [0.6, 1.6] of it is not trusted.
  auto plausible = [](double measured, double prior) {
    return measured > 0 ? std::clamp(measured, 0.6 * prior, 1.6 * prior) : prior;
  };
  for (int s = 0; s < kSegmentCount; ++s) {
    dims.radius[s] = plausible(twice_median(d[s]), typical.radius[s]);
  }
  // The torso's reach h across its axis in direction (cos φ, sin φ) is the ellipse's support
  // function, h² = a² cos² φ + b² sin² φ: least squares for a² (half-width) and b² (depth).
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  Eigen::Vector2d y = Eigen::Vector2d::Zero();
  for (int k = 0; k < kBins; ++k) {
    const double h = twice_median(torso[k]);
    if (h <= 0) continue;
    const double phi = (k + 0.5) / kBins * std::numbers::pi / 2;
    const Eigen::Vector2d row(std::pow(std::cos(phi), 2), std::pow(std::sin(phi), 2));
    A += row * row.transpose();
    y += row * h * h;
  }
  dims.torso_width = plausible(dims.radius[kTorso], typical.torso_width);
  if (std::abs(A.determinant()) > 1e-9) {
    const Eigen::Vector2d ab2 = A.ldlt().solve(y);
    if (ab2.x() > 0 && ab2.y() > 0) {
      dims.torso_width = plausible(std::sqrt(ab2.x()), typical.torso_width);
      dims.radius[kTorso] = plausible(std::sqrt(ab2.y()), typical.radius[kTorso]);
    }
  }
}

}  // namespace

void set_typical_radii(BodyDimensions& dims) {
  dims.radius = {0.6 * dims.shoulder_half, 0.3 * dims.head,       0.14 * dims.upper_arm,
                 0.09 * dims.forearm,      0.14 * dims.upper_arm, 0.09 * dims.forearm,
                 0.17 * dims.thigh,        0.13 * dims.calf,      0.17 * dims.thigh,
                 0.13 * dims.calf};
  dims.torso_width = 0.8 * dims.shoulder_half;
}

void measure_radii(BodyDimensions& dims, JointSet joints, const StickPose& pose,
                   const std::vector<SilhouetteRay>& rays) {
  const StickGeometry g = StickModel(dims, joints).geometry(pose);
  BodyDimensions typical = dims;
  set_typical_radii(typical);
  dims.radius = typical.radius;
  dims.torso_width = typical.torso_width;
  // Each pass reassigns the rays with the radii of the one before.
  for (int pass = 0; pass < 3; ++pass) measure_radii_once(dims, typical, g, rays);
}

BodyDimensions dimensions_from_height(double height_m) {
  BodyParameters body;
  body.height = height_m;
  const Skeleton s = build_humanoid(body);
  const auto p = joint_positions(s, Pose::neutral(s));
  NamedJoints joints;
  for (int i = 0; i < s.size(); ++i) joints[s[i].name] = p[i];
  BodyDimensions d =
      dimensions_from_joints(joints, "humanoid of height " + std::to_string(height_m));
  set_typical_radii(d);
  return d;
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
  // Horizontal centroids of height bands, as fractions of the standing height.
  const double height = cue.top_y;
  auto band_centroid = [&](double y0, double y1, int* count) {
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    *count = 0;
    for (int y = 0; y < hull.size.y(); ++y) {
      const double wy = g.origin.y() + g.voxel * (hull.lo.y() + y);
      if (wy < y0 || wy > y1) continue;
      for (int z = 0; z < hull.size.z(); ++z) {
        for (int x = 0; x < hull.size.x(); ++x) {
          if (!hull.cells[(static_cast<size_t>(y) * hull.size.z() + z) * hull.size.x() + x])
            continue;
          sum += Eigen::Vector2d(g.origin.x() + g.voxel * (hull.lo.x() + x),
                                 g.origin.z() + g.voxel * (hull.lo.z() + z));
          ++*count;
        }
      }
    }
    return *count ? Eigen::Vector2d(sum / *count) : Eigen::Vector2d::Zero();
  };
  const double centroid_y = cue.top_y - dims.head - dims.torso_half;
  int n = 0;
  cue.torso_xz =
      band_centroid(centroid_y - 0.5 * dims.torso_half, centroid_y + 0.5 * dims.torso_half, &n);
  int nf = 0, ns = 0;
  const Eigen::Vector2d feet = band_centroid(0.0, 0.035 * height, &nf);
  const Eigen::Vector2d shins = band_centroid(0.10 * height, 0.20 * height, &ns);
  // Toes reach ~0.11 H in front of the ankles; a smaller offset is not a direction.
  if (nf > 0 && ns > 0 && (feet - shins).norm() > 0.015 * height) {
    cue.forward_xz = (feet - shins).normalized();
  }
  return cue;
}

std::vector<StickPose> upright_hypotheses(const StickModel& model, const UprightCue& cue,
                                          int headings) {
  const BodyDimensions& d = model.dimensions();
  std::vector<double> yaws;
  if (cue.forward_xz) {
    // Facing +Z at yaw 0; yaw ψ faces (sin ψ, cos ψ) in (x, z).
    const double centre = std::atan2(cue.forward_xz->x(), cue.forward_xz->y());
    for (int k = -3; k <= 3; ++k) yaws.push_back(centre + k * kPi / 9);
  } else {
    for (int k = 0; k < std::max(1, headings); ++k) yaws.push_back(2 * kPi * k / headings);
  }
  std::vector<StickPose> out;
  for (const double yaw : yaws) {
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
