#include "models/retarget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "models/bvh_names.h"
#include "models/pose.h"

namespace simcap {
namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out.empty() ? "(none)" : out;
}

// The target joint whose centre the bone of `j` points at: its only child, skipping unmapped
// joints that have a single child themselves (vl5 -> vl3 -> vl1 when vl3 has no BVH joint).
// -1 when the chain branches first (the bone has no single direction).
int direction_child(const Skeleton& target, const std::vector<int>& source_of, int j) {
  for (int k = j;;) {
    const auto kids = target.children(k);
    if (kids.size() != 1) return -1;
    k = kids[0];
    if (source_of[k] >= 0) return k;
  }
}

double leg_length(const std::vector<Eigen::Vector3d>& p, int hip, int knee, int ankle) {
  return (p[knee] - p[hip]).norm() + (p[ankle] - p[knee]).norm();
}

}  // namespace

std::string RetargetReport::summary() const {
  char buf[200];
  std::string out = "naming: " + naming + "; " + std::to_string(mapped.size()) +
                    " BVH joints and sites drive the target\n";
  out += "BVH joints not mapped (their motion is lost): " + join(unmapped) + "\n";
  out += "BVH joints folded into mapped descendants: " + join(folded) + "\n";
  out += "target joints without a BVH joint (neutral relative to their parent): " +
         join(target_unmapped) + "\n";
  std::snprintf(buf, sizeof buf,
                "root trajectory scale (leg length ratio): %.4f; floor offset: %+.4f m, per-frame "
                "ground correction up to %.4f m\n",
                root_scale, floor_offset, ground_max);
  out += buf;
  std::snprintf(buf, sizeof buf, "source feet (joint centres; floor at their median low, %.4f m): ",
                source_feet.floor);
  out += buf + source_feet.summary() + "\n";
  out += "target feet (sole points; floor at 0): " + target_feet.summary() + "\n";
  return out;
}

Retargeted retarget_bvh(const BvhClip& clip, const Skeleton& target,
                        const RetargetOptions& options) {
  const int n_source = static_cast<int>(clip.joints.size());
  std::vector<std::string> names;
  for (const auto& j : clip.joints) names.push_back(j.name);
  const BvhNaming naming = map_bvh_names(names);

  RetargetReport report;
  report.naming = naming.convention;
  std::vector<int> source_of(target.size(), -1);
  std::vector<bool> drives(n_source, false);
  for (int i = 0; i < n_source; ++i) {
    const int t = naming.hanim[i].empty() ? -1 : target.find(naming.hanim[i]);
    if (t < 0) continue;
    source_of[t] = i;
    drives[i] = true;
    report.mapped.emplace_back(clip.joints[i].name, target[t].name);
  }
  const auto need = [&](const char* name) {
    const int t = target.find(name);
    if (t < 0 || source_of[t] < 0) {
      throw Error(clip.file.string() + ": cannot retarget: no BVH joint maps to '" + name +
                  "' (name table " + naming.convention + ")");
    }
    return t;
  };
  if (target[0].name != "humanoid_root") {
    throw Error("retarget: the target skeleton's root must be humanoid_root");
  }
  need("humanoid_root");
  const int t_hip[2] = {need("l_hip"), need("r_hip")};
  const int t_knee[2] = {need("l_knee"), need("r_knee")};
  const int t_ankle[2] = {need("l_talocrural"), need("r_talocrural")};

  // A BVH joint without a target joint still moves the target if a mapped joint lies below it,
  // because target joints take their BVH joint's world rotation.
  std::vector<bool> moves_target(n_source, false);
  for (int i = n_source - 1; i >= 0; --i) {
    const int t = naming.hanim[i].empty() ? -1 : target.find(naming.hanim[i]);
    if (t >= 0 && !target[t].is_site) moves_target[i] = true;
    if (moves_target[i] && clip.joints[i].parent >= 0) moves_target[clip.joints[i].parent] = true;
  }
  for (int i = 0; i < n_source; ++i) {
    if (drives[i]) continue;
    (moves_target[i] ? report.folded : report.unmapped).push_back(clip.joints[i].name);
  }
  for (int t = 0; t < target.size(); ++t) {
    if (!target[t].is_site && source_of[t] < 0) report.target_unmapped.push_back(target[t].name);
  }

  // Rest alignment: A[t] turns t's neutral bone direction into its BVH joint's rest bone
  // direction, so that W_t = R_s A_t points the target bone where the BVH bone points.
  const auto rest = bvh_joint_positions(clip, -1);
  auto centre = [&](int t) { return target[t].center; };
  std::vector<Eigen::Quaterniond> align(target.size(), Eigen::Quaterniond::Identity());
  {
    // The root only turns about the vertical: the two skeletons' pelvis shapes differ, their
    // facing may not.
    Eigen::Vector3d lateral_t = centre(t_hip[0]) - centre(t_hip[1]);
    Eigen::Vector3d lateral_s = rest[source_of[t_hip[0]]] - rest[source_of[t_hip[1]]];
    lateral_t.y() = 0;
    lateral_s.y() = 0;
    if (lateral_t.norm() > 1e-9 && lateral_s.norm() > 1e-9) {
      align[0] = Eigen::Quaterniond::FromTwoVectors(lateral_t, lateral_s);
    }
  }
  // A bone without a direction keeps its parent's alignment: a hand whose fingertips the clip
  // does not name continues its forearm.
  for (int t = 1; t < target.size(); ++t) {
    align[t] = align[target[t].parent];
    if (target[t].is_site || source_of[t] < 0) continue;
    const int k = direction_child(target, source_of, t);
    if (k < 0) continue;
    const Eigen::Vector3d dt = centre(k) - centre(t);
    const Eigen::Vector3d ds = rest[source_of[k]] - rest[source_of[t]];
    if (dt.norm() > 1e-9 && ds.norm() > 1e-9) {
      align[t] = Eigen::Quaterniond::FromTwoVectors(dt, ds);
    }
  }

  double source_leg = 0, target_leg = 0;
  std::vector<Eigen::Vector3d> centres;
  for (const auto& j : target.joints()) centres.push_back(j.center);
  for (int side = 0; side < 2; ++side) {
    source_leg +=
        leg_length(rest, source_of[t_hip[side]], source_of[t_knee[side]], source_of[t_ankle[side]]);
    target_leg += leg_length(centres, t_hip[side], t_knee[side], t_ankle[side]);
  }
  if (!(source_leg > 1e-6)) throw Error(clip.file.string() + ": the clip's legs have no length");
  report.root_scale = target_leg / source_leg;

  Retargeted out;
  out.motion.fps = clip.fps();
  const int frames = clip.frame_count();
  out.motion.frames.reserve(frames);
  std::vector<Eigen::Quaterniond> world(target.size());
  FootTrack source_track;
  source_track.fps = clip.fps();
  for (int f = 0; f < frames; ++f) {
    const auto g = bvh_forward_kinematics(clip, f);
    Pose pose = Pose::neutral(target);
    for (int t = 0; t < target.size(); ++t) {
      const int p = target[t].parent;
      if (source_of[t] >= 0 && !target[t].is_site) {
        world[t] = Eigen::Quaterniond(g[source_of[t]].linear()) * align[t];
      } else {
        world[t] = p < 0 ? Eigen::Quaterniond::Identity() : world[p];
      }
      if (!target[t].is_site) {
        pose.rotations[t] = (p < 0 ? world[t] : world[p].conjugate() * world[t]).normalized();
      }
    }
    // Put the target's hip midpoint where the clip's is, scaled by the leg-length ratio.
    pose.root_position.setZero();
    const auto at_origin = joint_positions(target, pose);
    const Eigen::Vector3d source_mid =
        0.5 * (g[source_of[t_hip[0]]].translation() + g[source_of[t_hip[1]]].translation());
    const Eigen::Vector3d target_mid = 0.5 * (at_origin[t_hip[0]] + at_origin[t_hip[1]]);
    pose.root_position = report.root_scale * source_mid - target_mid;
    out.motion.frames.push_back(std::move(pose));

    auto& feet = source_track.frames.emplace_back();
    for (int side = 0; side < 2; ++side) {
      const char* prefix = side == 0 ? "l_" : "r_";
      for (const char* part : {"talocrural", "metatarsophalangeal_2", "toe_tip"}) {
        const int t = target.find(std::string(prefix) + part);
        if (t >= 0 && source_of[t] >= 0) feet[side].push_back(g[source_of[t]].translation());
      }
    }
  }
  // The clip's feet are joint centres, not soles: their floor is where they rest most.
  report.source_feet = measure_feet(source_track, options.contact_height, options.min_contact_s,
                                    median_lowest_point(source_track));
  if (options.place_on_floor) {
    const FootTrack feet = humanoid_feet(target, out.motion);
    report.floor_offset = -median_lowest_point(feet);
    const double band = options.ground_band;
    for (int f = 0; f < frames; ++f) {
      double low = INFINITY;
      for (const auto& foot : feet.frames[f]) {
        for (const auto& p : foot) low = std::min(low, p.y() + report.floor_offset);
      }
      // Full correction up to one band above the floor, none from two bands (a jump).
      const double weight = band > 0 ? std::clamp(2 - low / band, 0.0, 1.0) : 0.0;
      const double lift = report.floor_offset - weight * low;
      out.motion.frames[f].root_position.y() += lift;
      report.ground_max = std::max(report.ground_max, std::abs(lift - report.floor_offset));
    }
  }
  report.target_feet = measure_feet(humanoid_feet(target, out.motion), options.contact_height,
                                    options.min_contact_s);
  out.report = std::move(report);
  return out;
}

}  // namespace simcap
