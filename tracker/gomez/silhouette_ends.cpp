// Geodesic extremities of the silhouette and their limbs (silhouette_ends.h).
#include "tracker/gomez/silhouette_ends.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <queue>
#include <utility>

namespace simcap::tracker::gomez {
namespace {

// Dijkstra over the silhouette's 8-connected working pixels (steps 1 and sqrt 2), lowering
// `dist` from `sources` (pixel indices) wherever it shortens the path.
void lower_distances(const FrameCues& cues, const std::vector<int>& sources,
                     std::vector<double>& dist) {
  const int W = cues.view.width, H = cues.view.height;
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  for (const int k : sources) {
    dist[k] = 0;
    queue.push({0.0, k});
  }
  while (!queue.empty()) {
    const auto [d, k] = queue.top();
    queue.pop();
    if (d > dist[k]) continue;
    const int u = k % W, v = k / W;
    for (int dv = -1; dv <= 1; ++dv) {
      for (int du = -1; du <= 1; ++du) {
        const int uu = u + du, vv = v + dv;
        if ((du == 0 && dv == 0) || uu < 0 || vv < 0 || uu >= W || vv >= H) continue;
        const int n = vv * W + uu;
        if (cues.cls[n] == 0) continue;
        const double e = d + (du != 0 && dv != 0 ? std::numbers::sqrt2 : 1.0);
        if (e < dist[n]) {
          dist[n] = e;
          queue.push({e, n});
        }
      }
    }
  }
}

}  // namespace

std::vector<SilhouetteEnd> silhouette_ends(const FrameCues& cues, const Eigen::Vector2d& trunk,
                                           double min_length, int max_ends) {
  std::vector<SilhouetteEnd> out;
  const View& view = cues.view;
  const int W = view.width, H = view.height;
  if (W <= 0 || H <= 0 || view.factor <= 0) return out;
  const auto full = [&](int k) {
    return Eigen::Vector2d(view.x0 + (k % W + 0.5) * view.factor - 0.5,
                           view.y0 + (k / W + 0.5) * view.factor - 0.5);
  };
  int seed = -1;
  double nearest = INFINITY;
  for (int k = 0; k < W * H; ++k) {
    if (cues.cls[k] == 0) continue;
    const double d = (full(k) - trunk).squaredNorm();
    if (d < nearest) {
      nearest = d;
      seed = k;
    }
  }
  if (seed < 0) return out;
  std::vector<double> from_trunk(static_cast<size_t>(W) * H, INFINITY);
  lower_distances(cues, {seed}, from_trunk);
  std::vector<double> dist = from_trunk;
  const auto on_border = [&](int k) {
    const int u = k % W, v = k / W;
    return u == 0 || v == 0 || u == W - 1 || v == H - 1;
  };
  // A limb's end is as far from the trunk as anything next to it: from the pixel found, uphill in
  // the distance from the trunk, a neighbour at a time (a wider step would cross to another limb
  // lying close), to where no neighbour is farther. From the middle of a long limb (far from both
  // the trunk and the end found on it) that is the end found again.
  const auto climb = [&](int k) {
    for (bool moved = true; moved;) {
      moved = false;
      const int u = k % W, v = k / W, r = 1;
      for (int vv = std::max(0, v - r); vv <= std::min(H - 1, v + r); ++vv) {
        for (int uu = std::max(0, u - r); uu <= std::min(W - 1, u + r); ++uu) {
          const int n = vv * W + uu;
          if (std::isfinite(from_trunk[n]) && from_trunk[n] > from_trunk[k]) {
            k = n;
            moved = true;
          }
        }
      }
    }
    return k;
  };
  // Each pixel found becomes a source, so that the next one is far from all of them: a limb
  // gives one extremity, not one per pixel of its end. The first one on the border makes the
  // whole border a source: a cut goes across the limbs it cuts.
  for (int tries = 0; static_cast<int>(out.size()) < max_ends && tries < 4 * max_ends; ++tries) {
    int far = -1;
    for (int k = 0; k < W * H; ++k) {
      if (std::isfinite(dist[k]) && (far < 0 || dist[k] > dist[far])) far = k;
    }
    if (far < 0 || dist[far] < min_length) break;
    std::vector<int> sources = {far};
    if (on_border(far)) {
      sources.clear();
      for (int k = 0; k < W * H; ++k) {
        if (cues.cls[k] != 0 && on_border(k)) sources.push_back(k);
      }
    } else {
      const int end = climb(far);
      if (dist[end] >= min_length && !on_border(end)) {
        out.push_back({full(end), from_trunk[end]});
        sources.push_back(end);
      }
    }
    lower_distances(cues, sources, dist);
  }
  return out;
}

std::vector<int> assign_ends(const std::vector<SilhouetteEnd>& ends,
                             const std::vector<PredictedEnd>& predicted) {
  std::vector<int> out(ends.size(), -1);
  std::vector<bool> taken(predicted.size(), false), explained(ends.size(), false);
  for (size_t i = 0; i < ends.size(); ++i) {
    for (size_t j = 0; j < predicted.size(); ++j) {
      if ((ends[i].pixel - predicted[j].pixel).norm() <= predicted[j].tolerance) {
        explained[i] = true;
        taken[j] = true;
      }
    }
  }
  std::vector<std::pair<double, std::pair<int, int>>> pairs;
  for (size_t i = 0; i < ends.size(); ++i) {
    if (explained[i]) continue;
    for (size_t j = 0; j < predicted.size(); ++j) {
      if (taken[j] || !predicted[j].proposable) continue;
      pairs.push_back({(ends[i].pixel - predicted[j].pixel).norm(),
                       {static_cast<int>(i), static_cast<int>(j)}});
    }
  }
  std::stable_sort(pairs.begin(), pairs.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [d, ij] : pairs) {
    const auto [i, j] = ij;
    if (out[i] >= 0 || taken[j]) continue;
    out[i] = j;
    taken[j] = true;
  }
  return out;
}

}  // namespace simcap::tracker::gomez
