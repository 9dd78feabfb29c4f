#include "tracker/unzueta/gesture_spotting.h"

#include <algorithm>
#include <numeric>

namespace simcap::tracker {

std::vector<double> kinetic_pseudo_energy(const std::vector<Eigen::Vector3d>& x, double fps) {
  std::vector<double> e(x.size(), 0.0);
  for (size_t i = 1; i < x.size(); ++i) e[i] = 0.5 * (x[i] - x[i - 1]).squaredNorm() * fps * fps;
  return e;
}

std::vector<Eigen::Vector3d> median_velocity_path(const std::vector<Eigen::Vector3d>& x,
                                                  int frames) {
  if (frames <= 1 || x.size() < 2) return x;
  const int n = static_cast<int>(x.size());
  std::vector<Eigen::Vector3d> v(x.size(), Eigen::Vector3d::Zero());
  for (int i = 1; i < n; ++i) v[i] = x[i] - x[i - 1];
  const int half = frames / 2;
  std::vector<Eigen::Vector3d> out(x.size());
  out[0] = x[0];
  std::vector<double> window(static_cast<size_t>(2 * half + 1));
  for (int i = 1; i < n; ++i) {
    Eigen::Vector3d m;
    for (int d = 0; d < 3; ++d) {
      for (int k = -half; k <= half; ++k) window[k + half] = v[std::clamp(i + k, 0, n - 1)][d];
      std::nth_element(window.begin(), window.begin() + half, window.end());
      m[d] = window[half];
    }
    out[i] = out[i - 1] + m;
  }
  return out;
}

std::vector<double> history_mean(const std::vector<double>& psE, int history) {
  std::vector<double> mean(psE.size());
  double sum = 0;
  for (size_t t = 0; t < psE.size(); ++t) {
    sum += psE[t];
    if (t >= static_cast<size_t>(history)) sum -= psE[t - history];
    mean[t] = sum / static_cast<double>(std::min<size_t>(t + 1, history));
  }
  return mean;
}

int spotting_delay(const std::vector<double>& psE, int t, int history, double threshold) {
  int starting_point = t;
  for (int i = std::max(0, t - (history - 1)); i <= t; ++i) {
    if (psE[i] < threshold) starting_point = i;
  }
  return t - starting_point;
}

std::vector<SpottedStretch> spot_gestures(const std::vector<double>& psE,
                                          const SpottingParams& params) {
  std::vector<SpottedStretch> out;
  const int n = static_cast<int>(psE.size());
  const std::vector<double> history = history_mean(psE, params.history);
  bool active = false, confirmed = false;
  int start = 0, delay = 0, detected = 0;
  // `below`: the first frame whose history mean is under the threshold again (n: none is, the
  // stretch ends at the last frame).
  auto close = [&](int below) {
    int end = below == n ? n - 1 : std::max(start, below - delay);
    if (params.delay_at_end && below < n) {
      end = start;
      for (int i = below; i > start; --i) {
        if (psE[i] >= params.threshold) {
          end = i;
          break;
        }
      }
    }
    // One frame is no path to recognise.
    if (confirmed && end > start && below - detected >= params.min_frames) {
      out.push_back({start, end});
    }
    active = false;
  };
  std::vector<double> window;
  for (int t = 0; t < n; ++t) {
    const double mean = history[t];
    if (!active && mean >= params.threshold) {
      delay = spotting_delay(psE, t, params.history, params.threshold);
      start = t - delay;
      detected = t;
      active = true;
      confirmed = false;
    } else if (active && mean < params.threshold) {
      close(t);
    }
    if (active && !confirmed) {
      window.assign(psE.begin() + std::max(0, t - params.history + 1), psE.begin() + t + 1);
      const auto kept =
          std::max<std::ptrdiff_t>(1, std::ssize(window) - std::max(0, params.drop_largest));
      std::nth_element(window.begin(), window.begin() + (kept - 1), window.end());
      confirmed =
          std::accumulate(window.begin(), window.begin() + kept, 0.0) / static_cast<double>(kept) >=
          params.threshold;
    }
  }
  if (active) close(n);
  return out;
}

SpottedStretch widen_to_motion(const std::vector<double>& psE, SpottedStretch s, int lo, int hi,
                               double fraction) {
  if (fraction <= 0) return s;
  const double peak = *std::max_element(psE.begin() + s.first, psE.begin() + s.last + 1);
  const double moving = fraction * fraction * peak;
  while (s.first > lo && psE[s.first - 1] >= moving) --s.first;
  while (s.last < hi && psE[s.last + 1] >= moving) ++s.last;
  return s;
}

}  // namespace simcap::tracker
