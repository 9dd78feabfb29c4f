#include "tracker/unzueta/gesture_evaluation.h"

#include <algorithm>
#include <optional>

#include "core/error.h"
#include "tracker/unzueta/gesture_normalization.h"

namespace simcap::tracker {

namespace {

constexpr std::array<GestureClassifierKind, 2> kKinds = {GestureClassifierKind::knn,
                                                         GestureClassifierKind::svm};

int limb_index(const std::string& limb, const std::string& corpus) {
  for (int l = 0; l < 2; ++l) {
    if (kGestureLimbs[l] == limb) return l;
  }
  throw Error(corpus + ": gestures.csv names limb '" + limb + "'; expected l_hand or r_hand");
}

// Signal index of a frame (the first one at or after it).
int index_at(const BodySignals& s, int frame) {
  return static_cast<int>(std::lower_bound(s.frames.begin(), s.frames.end(), frame) -
                          s.frames.begin());
}

double iou(int a0, int a1, int b0, int b1) {
  const int inter = std::min(a1, b1) - std::max(a0, b0) + 1;
  if (inter <= 0) return 0;
  return static_cast<double>(inter) / (std::max(a1, b1) - std::min(a0, b0) + 1);
}

// Spotted stretches of every limb, each matched to the true dynamic gesture of its limb with the
// largest IoU at or above the threshold (each true gesture at most once, best IoU first).
// `c`'s own signals are spotted; `smoothed` (them smoothed for recognition) widens each path.
std::vector<SpottedGesture> spot(const GestureCorpus& c, const BodySignals& smoothed,
                                 const GestureOptions& o) {
  std::vector<SpottedGesture> out;
  for (int l = 0; l < 2; ++l) {
    const auto energy = spotting_energy(c.signals.hand[l], c.fps, o);
    const std::vector<SpottedStretch> found = spot_gestures(energy, o.spotting);
    const std::vector<double> motion = kinetic_pseudo_energy(smoothed.hand[l], c.fps);
    const int n = static_cast<int>(motion.size());
    for (size_t i = 0; i < found.size(); ++i) {
      const int lo = i > 0 ? found[i - 1].last + 1 : 0;
      const int hi = i + 1 < found.size() ? found[i + 1].first - 1 : n - 1;
      const SpottedStretch p = widen_to_motion(motion, found[i], lo, hi, o.path_speed_fraction);
      const auto& f = c.signals.frames;
      out.push_back({kGestureLimbs[l],
                     f[found[i].first],
                     f[found[i].last],
                     "",
                     0,
                     f[p.first],
                     f[p.last],
                     {}});
    }
  }
  struct Pair {
    double iou;
    size_t spotted, truth;
  };
  std::vector<Pair> pairs;
  for (size_t i = 0; i < out.size(); ++i) {
    for (size_t t = 0; t < c.truth.size(); ++t) {
      const GestureInterval& g = c.truth[t];
      if (g.kind != "dynamic" || g.limb != out[i].limb) continue;
      const double v = iou(out[i].first_frame, out[i].last_frame, g.first_frame, g.last_frame);
      if (v >= o.match_iou) pairs.push_back({v, i, t});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) {
    return a.iou != b.iou ? a.iou > b.iou : a.spotted < b.spotted;
  });
  std::vector<bool> truth_used(c.truth.size(), false);
  for (const Pair& p : pairs) {
    if (!out[p.spotted].truth.empty() || truth_used[p.truth]) continue;
    out[p.spotted].truth = c.truth[p.truth].label;
    out[p.spotted].iou = p.iou;
    truth_used[p.truth] = true;
  }
  return out;
}

Eigen::VectorXd gesture_features(const GestureCorpus& c, const SpottedGesture& g,
                                 const GestureOptions& o) {
  const int l = limb_index(g.limb, c.name);
  const auto& path = c.signals.hand[l];
  return normalize_gesture({path.begin() + index_at(c.signals, g.path_first),
                            path.begin() + index_at(c.signals, g.path_last) + 1},
                           o.states, o.size);
}

// A classifier per limb; a limb with one label needs none.
struct LimbClassifiers {
  std::array<std::vector<Eigen::VectorXd>, 2> x;
  std::array<std::vector<std::string>, 2> y;
  std::array<std::optional<GestureClassifier>, 2> model;

  void train(GestureClassifierKind kind, int k) {
    for (int l = 0; l < 2; ++l) {
      if (x[l].empty()) continue;
      const bool single =
          std::all_of(y[l].begin(), y[l].end(), [&](const std::string& s) { return s == y[l][0]; });
      if (single) continue;
      model[l].emplace(kind, k);
      model[l]->train(x[l], y[l]);
    }
  }
  // "unknown" when the limb had no training samples.
  std::string predict(int l, const Eigen::VectorXd& v) const {
    if (model[l]) return model[l]->predict(v);
    return y[l].empty() ? std::string("unknown") : y[l][0];
  }
};

void add(Confusion& c, const std::string& truth, const std::string& predicted) {
  for (const std::string* s : {&truth, &predicted}) {
    const auto it = std::lower_bound(c.labels.begin(), c.labels.end(), *s);
    if (it != c.labels.end() && *it == *s) continue;
    const auto at = it - c.labels.begin();
    c.labels.insert(it, *s);
    for (auto& row : c.counts) row.insert(row.begin() + at, 0);
    c.counts.insert(c.counts.begin() + at, std::vector<long>(c.labels.size(), 0));
  }
  auto index = [&](const std::string& s) {
    return static_cast<size_t>(std::lower_bound(c.labels.begin(), c.labels.end(), s) -
                               c.labels.begin());
  };
  ++c.counts[index(truth)][index(predicted)];
  ++c.total;
  if (truth == predicted) ++c.correct;
  c.accuracy = static_cast<double>(c.correct) / static_cast<double>(c.total);
}

}  // namespace

std::vector<double> spotting_energy(const std::vector<Eigen::Vector3d>& hand, double fps,
                                    const GestureOptions& o) {
  std::vector<Eigen::Vector3d> path = median_velocity_path(hand, o.spotting.velocity_median);
  smooth_path(path, o.smooth_sigma);
  return kinetic_pseudo_energy(path, fps);
}

GestureResults evaluate_gestures(const std::vector<GestureCorpus>& raw_corpora,
                                 const GestureOptions& o) {
  if (raw_corpora.size() < 2) {
    throw Error(
        "gestures: need at least two corpora (each one subject); every corpus is "
        "recognised by classifiers trained on the others");
  }
  std::vector<GestureCorpus> corpora = raw_corpora;
  std::vector<std::vector<SpottedGesture>> spotted;
  for (size_t k = 0; k < corpora.size(); ++k) {
    for (const auto& g : corpora[k].truth) limb_index(g.limb, corpora[k].name);
    smooth_signals(corpora[k].signals, o.smooth_sigma);
    spotted.push_back(spot(raw_corpora[k], corpora[k].signals, o));
  }
  GestureResults r;
  for (size_t test = 0; test < corpora.size(); ++test) {
    const GestureCorpus& c = corpora[test];
    std::map<GestureClassifierKind, LimbClassifiers> dynamic;
    LimbClassifiers poses;
    for (size_t train = 0; train < corpora.size(); ++train) {
      if (train == test) continue;
      const GestureCorpus& t = corpora[train];
      for (const auto& g : spotted[train]) {
        if (g.truth.empty()) continue;
        const int l = limb_index(g.limb, t.name);
        const Eigen::VectorXd v = gesture_features(t, g, o);
        for (auto kind : kKinds) {
          dynamic[kind].x[l].push_back(v);
          dynamic[kind].y[l].push_back(g.truth);
        }
      }
      for (const auto& g : t.truth) {
        if (g.kind != "static") continue;
        const int l = limb_index(g.limb, t.name);
        for (int i = index_at(t.signals, g.first_frame);
             i < static_cast<int>(t.signals.frames.size()) && t.signals.frames[i] <= g.last_frame;
             i += o.pose_stride) {
          poses.x[l].push_back(t.signals.hand[l][i]);
          poses.y[l].push_back(g.label);
        }
      }
    }
    for (auto kind : kKinds) dynamic[kind].train(kind, o.k);
    poses.train(GestureClassifierKind::knn, o.k);

    CorpusGestures out;
    out.name = c.name;
    out.spotted = spotted[test];
    const size_t n = c.signals.frames.size();
    // Held poses first, then the spotted gestures over them.
    for (int l = 0; l < 2; ++l) {
      out.stream[l].resize(n);
      for (size_t i = 0; i < n; ++i) out.stream[l][i] = poses.predict(l, c.signals.hand[l][i]);
    }
    for (auto& g : out.spotted) {
      const int l = limb_index(g.limb, c.name);
      const Eigen::VectorXd v = gesture_features(c, g, o);
      for (auto kind : kKinds) g.predicted[kind] = dynamic[kind].predict(l, v);
      for (int i = index_at(c.signals, g.first_frame);
           i < static_cast<int>(n) && c.signals.frames[i] <= g.last_frame; ++i) {
        out.stream[l][i] = g.predicted[GestureClassifierKind::knn];
      }
      if (g.truth.empty()) continue;
      ++out.matched;
      for (auto kind : kKinds)
        add(r.recognition[kind], g.limb + ":" + g.truth, g.limb + ":" + g.predicted[kind]);
    }
    for (const auto& g : c.truth) {
      const int l = limb_index(g.limb, c.name);
      if (g.kind == "dynamic") ++out.truth_count;
      for (int i = index_at(c.signals, g.first_frame);
           i < static_cast<int>(n) && c.signals.frames[i] <= g.last_frame; ++i) {
        ++out.label_frames;
        if (out.stream[l][i] == g.label) ++out.label_correct;
        if (g.kind != "static") continue;
        const bool in_gesture =
            std::any_of(out.spotted.begin(), out.spotted.end(), [&](const auto& s) {
              return s.limb == g.limb && s.first_frame <= c.signals.frames[i] &&
                     c.signals.frames[i] <= s.last_frame;
            });
        if (in_gesture) continue;
        ++out.pose_frames;
        const std::string p = poses.predict(l, c.signals.hand[l][i]);
        if (p == g.label) ++out.pose_correct;
        add(r.poses, g.limb + ":" + g.label, g.limb + ":" + p);
      }
    }
    r.spotted += static_cast<long>(out.spotted.size());
    r.truth_count += out.truth_count;
    r.matched += out.matched;
    r.corpora.push_back(std::move(out));
  }
  r.precision = r.spotted ? static_cast<double>(r.matched) / static_cast<double>(r.spotted) : 0;
  r.recall =
      r.truth_count ? static_cast<double>(r.matched) / static_cast<double>(r.truth_count) : 0;
  r.f1 = r.precision + r.recall > 0 ? 2 * r.precision * r.recall / (r.precision + r.recall) : 0;
  long frames = 0, correct = 0;
  for (const auto& c : r.corpora) {
    frames += c.label_frames;
    correct += c.label_correct;
  }
  r.label_accuracy = frames ? static_cast<double>(correct) / static_cast<double>(frames) : 0;
  return r;
}

}  // namespace simcap::tracker
