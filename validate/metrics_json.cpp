#include "validate/metrics_json.h"

#include <cmath>

namespace simcap {

namespace {

using Json = nlohmann::ordered_json;

double mm(double v) {
  return std::round(v * 1e4) / 1e4;
}

double unit(double v) {
  return std::round(v * 1e7) / 1e7;
}

Json group_json(const VisibilityGroup& g, const char* key) {
  Json j;
  if (g.visible_cameras >= 0) {
    j[key] = g.visible_cameras;
  } else {
    j[key] = g.label;
  }
  j["count"] = g.count;
  j["mpjpe_mm"] = g.count > 0 ? Json(mm(g.mpjpe_mm)) : Json(nullptr);
  return j;
}

Json pixels_json(const PixelErrors& p) {
  if (p.count == 0) return {{"count", 0}};
  return {{"count", p.count},
          {"median_px", mm(p.median_px)},
          {"mean_px", mm(p.mean_px)},
          {"p90_px", mm(p.p90_px)},
          {"max_px", mm(p.max_px)}};
}

}  // namespace

Json metrics_to_json(const Evaluation& ev, const std::string& dataset, const std::string& track) {
  Json j;
  j["schema"] = kMetricsSchema;
  j["dataset"] = dataset;
  j["track"] = track;
  j["frame_count"] = ev.frames.size();
  j["first_frame"] = ev.frames.front();
  j["last_frame"] = ev.frames.back();
  j["joints"] = ev.joints;
  j["mpjpe_mm"] = mm(ev.mpjpe_mm);
  j["pa_mpjpe_mm"] = mm(ev.pa_mpjpe_mm);
  j["pck"] = Json::array();
  for (const auto& p : ev.pck) {
    j["pck"].push_back({{"threshold_mm", p.threshold_mm}, {"fraction", unit(p.fraction)}});
  }
  j["rmse_mean_mm"] = mm(ev.rmse_mean_mm);
  j["wrists_elbows_mm"] = mm(ev.wrists_elbows_mm);
  // One camera: the error's mean components along and across its rays; null otherwise.
  const auto ray = [&](const std::optional<RaySplit>& r) -> Json {
    if (!r) return nullptr;
    return {{"along_mm", mm(r->along_mm)}, {"across_mm", mm(r->across_mm)}};
  };
  j["camera_ray"] = ray(ev.ray);
  j["per_joint"] = Json::array();
  for (const auto& s : ev.per_joint) {
    j["per_joint"].push_back({{"joint", s.joint},
                              {"mpjpe_mm", mm(s.mpjpe_mm)},
                              {"pa_mpjpe_mm", mm(s.pa_mpjpe_mm)},
                              {"rmse_mm", mm(s.rmse_mm)},
                              {"max_mm", mm(s.max_mm)},
                              {"camera_ray", ray(s.ray)}});
  }
  j["per_frame"] = Json::array();
  for (const auto& s : ev.per_frame) {
    j["per_frame"].push_back({{"frame", s.frame},
                              {"mpjpe_mm", mm(s.mpjpe_mm)},
                              {"pa_mpjpe_mm", mm(s.pa_mpjpe_mm)},
                              {"camera_ray", ray(s.ray)}});
  }
  if (ev.angles.empty()) {
    j["angles"] = nullptr;
  } else {
    Json a;
    a["rmse_mean_rad"] = unit(ev.angle_rmse_mean_rad);
    a["per_joint"] = Json::array();
    for (const auto& s : ev.angles) {
      a["per_joint"].push_back({{"joint", s.joint},
                                {"rmse_rad", unit(s.rmse_rad)},
                                {"mean_rad", unit(s.mean_rad)},
                                {"max_rad", unit(s.max_rad)}});
    }
    j["angles"] = a;
  }
  if (ev.by_visible_cameras.empty()) {
    j["visibility"] = nullptr;
  } else {
    Json v;
    v["camera_count"] = ev.camera_count;
    v["by_visible_cameras"] = Json::array();
    for (const auto& g : ev.by_visible_cameras) {
      v["by_visible_cameras"].push_back(group_json(g, "cameras"));
    }
    v["by_occlusion"] = Json::array();
    for (const auto& g : ev.by_occlusion) v["by_occlusion"].push_back(group_json(g, "occlusion"));
    j["visibility"] = v;
  }
  const FailureSummary& f = ev.failures;
  Json fj;
  fj["threshold_mm"] = f.threshold_mm;
  fj["failed_frames"] = f.failed_frames;
  fj["failed_fraction"] = unit(f.failed_fraction);
  fj["episode_count"] = f.episodes.size();
  fj["mean_recovery_frames"] = unit(f.mean_recovery_frames);
  fj["max_recovery_frames"] = f.max_recovery_frames;
  fj["episodes"] = Json::array();
  for (const auto& e : f.episodes) {
    fj["episodes"].push_back(
        {{"first_frame", e.first_frame}, {"frames", e.frames}, {"recovered", e.recovered}});
  }
  j["failures"] = fj;
  return j;
}

Json effector_scores_json(const std::optional<EffectorScores>& scores) {
  if (!scores) return nullptr;
  Json j;
  j["effector_frames"] = scores->frames;
  j["lost"] = scores->lost;
  j["lost_fraction"] = unit(scores->lost_fraction);
  j["all"] = pixels_json(scores->all);
  j["visible"] = pixels_json(scores->visible);
  j["self_occluded"] = pixels_json(scores->self_occluded);
  j["per_effector"] = Json::array();
  for (const auto& e : scores->per_effector) {
    j["per_effector"].push_back({{"camera", e.camera},
                                 {"effector", e.effector},
                                 {"joint", e.joint},
                                 {"frames", e.frames},
                                 {"lost", e.lost},
                                 {"all", pixels_json(e.all)},
                                 {"visible", pixels_json(e.visible)},
                                 {"self_occluded", pixels_json(e.self_occluded)}});
  }
  return j;
}

}  // namespace simcap
