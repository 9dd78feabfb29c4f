#include "validate/keypoint_ap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.h"

namespace simcap {
namespace {

constexpr int kMaxDetections = 20;  // COCOeval's maxDets for keypoints
constexpr int kRecallSteps = 101;

// np.linspace(start, stop, n): start + i * step, the last value exactly stop.
double linspace(double start, double stop, int n, int i) {
  return i == n - 1 ? stop : start + i * ((stop - start) / (n - 1));
}

bool labelled(const TruthKeypoint& t) {
  return t.known && t.visibility != VisibilityLabel::out_of_frame;
}

// COCOeval ignores an annotation without labelled keypoints (num_keypoints 0).
bool has_oks_keypoint(const ActorView& truth, const KeypointLayout& layout) {
  for (int k = 0; k < layout.size(); ++k) {
    if (layout.keypoints[k].sigma > 0 && labelled(truth.keypoints[k])) return true;
  }
  return false;
}

}  // namespace

std::optional<double> keypoint_oks(const ActorView& truth, const DetectedPerson& detection,
                                   const KeypointLayout& layout) {
  double sum = 0;
  int n = 0;
  const double eps = std::numeric_limits<double>::epsilon();  // np.spacing(1)
  for (int k = 0; k < layout.size(); ++k) {
    const double sigma = layout.keypoints[k].sigma;
    const TruthKeypoint& t = truth.keypoints[k];
    if (sigma <= 0 || !labelled(t)) continue;
    const DetectedKeypoint& d = detection.keypoints[k];
    const double d2 =
        (d.x - t.pixel.x()) * (d.x - t.pixel.x()) + (d.y - t.pixel.y()) * (d.y - t.pixel.y());
    const double var = (2 * sigma) * (2 * sigma);
    sum += std::exp(-(d2 / var / (truth.area + eps) / 2));
    ++n;
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

CocoKeypointAp coco_keypoint_ap(const KeypointTruth& truth, const Detections& detections) {
  if (detections.layout() != truth.layout() || detections.frames() != truth.frames() ||
      detections.cameras() != truth.cameras()) {
    throw Error("COCO AP: the detections are not of the truth's layout, frames and cameras");
  }
  const KeypointLayout& layout = keypoint_layout(truth.layout());
  const int cameras = static_cast<int>(truth.cameras().size());
  const int actors = static_cast<int>(truth.actors().size());
  constexpr int kT = CocoKeypointAp::kThresholds;
  CocoKeypointAp out;
  // Per threshold, every image's scored detections, images in order.
  std::vector<std::vector<std::pair<double, bool>>> scored(kT);
  for (int f = 0; f < truth.frames(); ++f) {
    for (int c = 0; c < cameras; ++c) {
      std::vector<const DetectedPerson*> dts;
      for (const DetectedPerson& p : detections.at(f, c)) dts.push_back(&p);
      std::stable_sort(
          dts.begin(), dts.end(),
          [](const DetectedPerson* a, const DetectedPerson* b) { return a->score > b->score; });
      if (dts.size() > static_cast<size_t>(kMaxDetections)) dts.resize(kMaxDetections);
      out.detections += static_cast<int>(dts.size());
      // oks[d][g] over the actors COCOeval does not ignore (see validate/README.md).
      std::vector<std::vector<double>> oks(dts.size());
      int gts = 0;
      for (int a = 0; a < actors; ++a) {
        const ActorView& view = truth.at(f, c, a);
        if (!view.annotated || !has_oks_keypoint(view, layout)) continue;
        for (size_t d = 0; d < dts.size(); ++d)
          oks[d].push_back(*keypoint_oks(view, *dts[d], layout));
        ++gts;
      }
      out.truths += gts;
      for (int t = 0; t < kT; ++t) {
        const double threshold = linspace(0.5, 0.95, kT, t);
        std::vector<bool> taken(static_cast<size_t>(gts), false);
        for (size_t d = 0; d < dts.size(); ++d) {
          double best_oks = std::min(threshold, 1 - 1e-10);
          int best = -1;
          for (int g = 0; g < gts; ++g) {
            if (taken[g] || oks[d][g] < best_oks) continue;
            best_oks = oks[d][g];
            best = g;
          }
          if (best >= 0) taken[best] = true;
          scored[t].emplace_back(dts[d]->score, best >= 0);
        }
      }
    }
  }
  if (out.truths == 0) return out;
  for (int t = 0; t < kT; ++t) {
    auto& list = scored[t];
    std::stable_sort(list.begin(), list.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    const size_t n = list.size();
    std::vector<double> recall(n), precision(n);
    double tp = 0, fp = 0;
    for (size_t i = 0; i < n; ++i) {
      (list[i].second ? tp : fp) += 1;
      recall[i] = tp / out.truths;
      precision[i] = tp / (tp + fp + std::numeric_limits<double>::epsilon());
    }
    for (size_t i = n; i-- > 1;) precision[i - 1] = std::max(precision[i - 1], precision[i]);
    double sum = 0;
    for (int r = 0; r < kRecallSteps; ++r) {
      const double level = linspace(0.0, 1.0, kRecallSteps, r);
      const size_t i = static_cast<size_t>(std::lower_bound(recall.begin(), recall.end(), level) -
                                           recall.begin());
      if (i < n) sum += precision[i];
    }
    out.ap_at[t] = sum / kRecallSteps;
    out.recall_at[t] = n ? recall.back() : 0.0;
  }
  const auto mean = [](const auto& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / v.size();
  };
  out.ap = mean(out.ap_at);
  out.ar = mean(out.recall_at);
  out.ap50 = out.ap_at[0];
  out.ap75 = out.ap_at[5];
  return out;
}

}  // namespace simcap
