#include "sim/capture_clock.h"

#include <algorithm>
#include <cmath>

#include "sim/random.h"

namespace simcap {
namespace {

enum Stream : std::uint64_t { kSyncOffset = 11 };

}  // namespace

CaptureClock::CaptureClock(const Scene& scene)
    : fps_(scene.render.fps), first_frame_(scene.render.first_frame) {
  const CaptureTiming& t = scene.timing;
  for (size_t c = 0; c < scene.cameras.size(); ++c) {
    double ms = 0;
    if (!t.offset_ms.empty()) {
      ms = t.offset_ms.at(c);
    } else if (t.offset_sigma_ms > 0) {
      ms = t.offset_sigma_ms *
           standard_normal(random_bits(t.seed, {kSyncOffset, text_key(scene.cameras[c].name)}));
    }
    offset_s_.push_back(1e-3 * ms);
    heights_.push_back(scene.cameras[c].height);
  }
  readout_s_ = 1e-3 * t.readout_ms;
  if (scene.render.samples_per_pixel > 1) exposure_s_ = scene.render.shutter / fps_;
  const double window = readout_s_ + exposure_s_;
  if (readout_s_ > 0) {
    time_steps_ = std::min(129, 1 + static_cast<int>(std::ceil(window * fps_ * kStepsPerFrame)));
  } else if (exposure_s_ > 0) {
    time_steps_ = 3;
    still_step_ = 1;
  }
  for (size_t c = 0; c < offset_s_.size(); ++c) {
    auto g = std::find_if(groups_.begin(), groups_.end(),
                          [&](const Group& x) { return x.offset_s == offset_s_[c]; });
    if (g == groups_.end()) {
      Group n;
      n.offset_s = offset_s_[c];
      n.begin_s = n.offset_s - 0.5 * exposure_s_;
      n.end_s = n.offset_s + readout_s_ + 0.5 * exposure_s_;
      groups_.push_back(n);
      g = groups_.end() - 1;
    }
    g->cameras.push_back(static_cast<int>(c));
    group_of_.push_back(static_cast<int>(g - groups_.begin()));
  }
  still_ = window == 0 && groups_.size() <= 1 && (groups_.empty() || groups_[0].offset_s == 0);
}

double CaptureClock::frame_time(int frame) const {
  return (first_frame_ + frame) / fps_;
}

double CaptureClock::row_offset_s(int camera, double row) const {
  const int h = heights_.at(camera);
  const double share = h > 1 ? std::clamp(row, 0.0, h - 1.0) / (h - 1) : 0.0;
  return offset_s_[camera] + readout_s_ * share;
}

RayTimes CaptureClock::ray_times(int camera) const {
  const Group& g = groups_.at(group_of_.at(camera));
  const double length = g.end_s - g.begin_s;
  RayTimes t;
  if (length <= 0) return t;
  const int h = heights_[camera];
  t.row0 = static_cast<float>((g.offset_s - g.begin_s) / length);
  t.per_row = h > 1 ? static_cast<float>(readout_s_ / (h - 1) / length) : 0.f;
  t.exposure = static_cast<float>(exposure_s_ / length);
  return t;
}

}  // namespace simcap
