#include "validate/evaluation.h"

#include <algorithm>

#include "core/error.h"

namespace simcap {

namespace {

constexpr double kMm = 1000.0;

VisibilityGroup group(std::string label, int cameras, const std::vector<double>& errors) {
  return {std::move(label), cameras, static_cast<long>(errors.size()), mean_value(errors)};
}

void check_shapes(const EvaluationInput& in) {
  const size_t n = in.frames.size();
  const auto cols = static_cast<Eigen::Index>(in.joints.size());
  if (n == 0) throw Error("evaluate: no frames to compare");
  if (in.truth.size() != n || in.estimate.size() != n) throw Error("evaluate: frame counts differ");
  for (size_t f = 0; f < n; ++f) {
    if (in.truth[f].cols() != cols || in.estimate[f].cols() != cols) {
      throw Error("evaluate: joint counts differ in frame " + std::to_string(in.frames[f]));
    }
  }
  if (!in.views.empty()) {
    if (in.views.size() != n) throw Error("evaluate: visibility frame count differs");
    for (const auto& v : in.views) {
      if (v.size() != in.joints.size()) throw Error("evaluate: visibility joint count differs");
    }
  }
  if (!in.angle_joints.empty()) {
    if (in.truth_rotations.size() != n || in.estimate_rotations.size() != n) {
      throw Error("evaluate: angle frame counts differ");
    }
    for (size_t f = 0; f < n; ++f) {
      if (in.truth_rotations[f].size() != in.angle_joints.size() ||
          in.estimate_rotations[f].size() != in.angle_joints.size()) {
        throw Error("evaluate: angle joint counts differ");
      }
    }
  }
}

FailureSummary failures(const std::vector<int>& frames, const std::vector<double>& per_frame,
                        double threshold) {
  FailureSummary s;
  s.threshold_mm = threshold;
  s.episodes = failure_episodes(frames, per_frame, threshold);
  s.failed_frames = std::count_if(per_frame.begin(), per_frame.end(),
                                  [threshold](double e) { return e > threshold; });
  s.failed_fraction = static_cast<double>(s.failed_frames) / static_cast<double>(per_frame.size());
  std::vector<double> recovery;
  for (const auto& e : s.episodes) {
    if (!e.recovered) continue;
    recovery.push_back(e.frames);
    s.max_recovery_frames = std::max(s.max_recovery_frames, e.frames);
  }
  s.mean_recovery_frames = mean_value(recovery);
  return s;
}

}  // namespace

const std::vector<std::string>& wrist_elbow_joints() {
  static const std::vector<std::string> names = {"l_elbow", "r_elbow", "l_radiocarpal",
                                                 "r_radiocarpal"};
  return names;
}

const char* occlusion_name(Occlusion o) {
  switch (o) {
    case Occlusion::none:
      return "unoccluded";
    case Occlusion::self:
      return "self_occluded";
    case Occlusion::scene:
      return "scene_occluded";
  }
  return "unoccluded";
}

Evaluation evaluate(const EvaluationInput& in, const EvaluationOptions& options) {
  check_shapes(in);
  const size_t frames = in.frames.size();
  const size_t joints = in.joints.size();
  std::vector<int> wrist_elbow;
  for (const auto& name : wrist_elbow_joints()) {
    const auto it = std::find(in.joints.begin(), in.joints.end(), name);
    if (it == in.joints.end()) throw Error("evaluate: joint '" + name + "' is not evaluated");
    wrist_elbow.push_back(static_cast<int>(it - in.joints.begin()));
  }

  Evaluation ev;
  ev.joints = in.joints;
  ev.frames = in.frames;
  ev.camera_count = in.camera_count;
  std::vector<double> all, all_pa, per_frame_mpjpe, wrist_elbow_errors;
  std::vector<std::vector<double>> joint_err(joints), joint_pa(joints);
  std::vector<std::vector<double>> by_cameras(in.views.empty() ? 0 : in.camera_count + 1);
  std::vector<std::vector<double>> by_occlusion(in.views.empty() ? 0 : 3);
  std::vector<std::vector<double>> joint_along(joints), joint_across(joints);
  std::vector<double> all_along, all_across;
  for (size_t f = 0; f < frames; ++f) {
    const Eigen::VectorXd d = kMm * joint_distances(in.truth[f], in.estimate[f]);
    const Eigen::VectorXd pa =
        kMm * joint_distances(in.truth[f], procrustes_aligned(in.truth[f], in.estimate[f]));
    RaySplit frame_ray;
    for (size_t j = 0; j < joints; ++j) {
      all.push_back(d[j]);
      all_pa.push_back(pa[j]);
      joint_err[j].push_back(d[j]);
      joint_pa[j].push_back(pa[j]);
      if (in.camera_centre) {
        const Eigen::Vector3d ray = (in.truth[f].col(j) - *in.camera_centre).normalized();
        const Eigen::Vector3d e = in.estimate[f].col(j) - in.truth[f].col(j);
        const double along = e.dot(ray);
        joint_along[j].push_back(kMm * std::abs(along));
        joint_across[j].push_back(kMm * (e - along * ray).norm());
        all_along.push_back(joint_along[j].back());
        all_across.push_back(joint_across[j].back());
        frame_ray.along_mm += joint_along[j].back() / joints;
        frame_ray.across_mm += joint_across[j].back() / joints;
      }
      if (!in.views.empty()) {
        const JointSight& v = in.views[f][j];
        by_cameras.at(std::clamp(v.visible_cameras, 0, in.camera_count)).push_back(d[j]);
        by_occlusion[static_cast<int>(v.occlusion)].push_back(d[j]);
      }
    }
    for (int j : wrist_elbow) wrist_elbow_errors.push_back(d[j]);
    ev.per_frame.push_back({in.frames[f], d.mean(), pa.mean(), {}});
    if (in.camera_centre) ev.per_frame.back().ray = frame_ray;
    per_frame_mpjpe.push_back(d.mean());
  }
  ev.mpjpe_mm = mean_value(all);
  ev.pa_mpjpe_mm = mean_value(all_pa);
  ev.wrists_elbows_mm = mean_value(wrist_elbow_errors);
  for (double t : options.pck_thresholds_mm) ev.pck.push_back({t, pck(all, t)});
  std::vector<double> rmse;
  for (size_t j = 0; j < joints; ++j) {
    const auto& e = joint_err[j];
    ev.per_joint.push_back({in.joints[j],
                            mean_value(e),
                            mean_value(joint_pa[j]),
                            root_mean_square(e),
                            *std::max_element(e.begin(), e.end()),
                            {}});
    rmse.push_back(ev.per_joint.back().rmse_mm);
    if (in.camera_centre) {
      ev.per_joint.back().ray = RaySplit{mean_value(joint_along[j]), mean_value(joint_across[j])};
    }
  }
  if (in.camera_centre) ev.ray = RaySplit{mean_value(all_along), mean_value(all_across)};
  ev.rmse_mean_mm = mean_value(rmse);

  std::vector<double> angle_rmse;
  for (size_t k = 0; k < in.angle_joints.size(); ++k) {
    std::vector<double> e;
    for (size_t f = 0; f < frames; ++f) {
      e.push_back(rotation_angle(in.truth_rotations[f][k], in.estimate_rotations[f][k]));
    }
    ev.angles.push_back({in.angle_joints[k], root_mean_square(e), mean_value(e),
                         *std::max_element(e.begin(), e.end())});
    angle_rmse.push_back(ev.angles.back().rmse_rad);
  }
  ev.angle_rmse_mean_rad = mean_value(angle_rmse);

  for (size_t k = 0; k < by_cameras.size(); ++k) {
    ev.by_visible_cameras.push_back(group(std::to_string(k) + (k == 1 ? " camera" : " cameras"),
                                          static_cast<int>(k), by_cameras[k]));
  }
  for (size_t k = 0; k < by_occlusion.size(); ++k) {
    ev.by_occlusion.push_back(
        group(occlusion_name(static_cast<Occlusion>(k)), -1, by_occlusion[k]));
  }
  ev.failures = failures(in.frames, per_frame_mpjpe, options.failure_threshold_mm);
  return ev;
}

}  // namespace simcap
