#include "validate/summary_text.h"

#include <cstdio>

namespace simcap {

namespace {

void line(std::string& out, const std::string& name, const char* format, double v,
          const char* unit) {
  char value[64];
  std::snprintf(value, sizeof value, format, v);
  char buf[160];
  std::snprintf(buf, sizeof buf, "  %-34s %10s%s%s\n", name.c_str(), value, *unit ? " " : "", unit);
  out += buf;
}

}  // namespace

std::string metrics_summary_text(const Evaluation& ev) {
  std::string s;
  line(s, "frames", "%.0f", static_cast<double>(ev.frames.size()), "");
  line(s, "joints", "%.0f", static_cast<double>(ev.joints.size()), "");
  line(s, "MPJPE", "%.1f", ev.mpjpe_mm, "mm");
  line(s, "PA-MPJPE", "%.1f", ev.pa_mpjpe_mm, "mm");
  for (const auto& p : ev.pck) {
    char name[48];
    std::snprintf(name, sizeof name, "PCK @ %.0f mm", p.threshold_mm);
    line(s, name, "%.1f", 100.0 * p.fraction, "%");
  }
  line(s, "per-point RMSE (mean over joints)", "%.1f", ev.rmse_mean_mm, "mm");
  line(s, "wrists and elbows", "%.1f", ev.wrists_elbows_mm, "mm");
  if (ev.ray) {
    line(s, "along the camera rays (depth)", "%.1f", ev.ray->along_mm, "mm");
    line(s, "across the camera rays (image)", "%.1f", ev.ray->across_mm, "mm");
  }
  if (!ev.angles.empty()) line(s, "joint-angle RMSE", "%.3f", ev.angle_rmse_mean_rad, "rad");
  char name[64];
  std::snprintf(name, sizeof name, "failed frames (> %.0f mm)", ev.failures.threshold_mm);
  line(s, name, "%.0f", static_cast<double>(ev.failures.failed_frames), "");
  return s;
}

std::string effector_summary_text(const EffectorScores& scores) {
  std::string s;
  line(s, "2D end-effectors, median error", "%.1f", scores.all.median_px, "px");
  if (scores.self_occluded.count > 0) {
    line(s, "2D end-effectors, self-occluded", "%.1f", scores.self_occluded.median_px, "px");
  }
  line(s, "2D end-effectors, lost", "%.2f", 100.0 * scores.lost_fraction, "%");
  return s;
}

}  // namespace simcap
