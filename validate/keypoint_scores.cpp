#include "validate/keypoint_scores.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "core/error.h"

namespace simcap {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double ratio(int a, int b) {
  return b > 0 ? static_cast<double>(a) / b : kNaN;
}

// The layout keypoint at an H-Anim joint centre; -1 when the layout has none there.
int hanim_index(const KeypointLayout& layout, std::string_view joint) {
  for (int k = 0; k < layout.size(); ++k) {
    if (layout.keypoints[k].truth == TruthKind::hanim_joint &&
        layout.keypoints[k].truth_name == joint) {
      return k;
    }
  }
  return -1;
}

Eigen::Vector2d pixel_of(const DetectedKeypoint& d) {
  return {d.x, d.y};
}

}  // namespace

std::string_view visibility_class_name(int v) {
  return v == static_cast<int>(VisibilityLabel::missing)
             ? "unlabelled"
             : visibility_label_name(static_cast<VisibilityLabel>(v));
}

double KeypointGroup::miss_rate() const {
  return keypoints > 0 ? 1.0 - ratio(detected, keypoints) : kNaN;
}

double KeypointGroup::median_px() const {
  if (errors_px.empty()) return kNaN;
  std::vector<double> e = errors_px;
  const size_t m = e.size() / 2;
  std::nth_element(e.begin(), e.begin() + static_cast<long>(m), e.end());
  if (e.size() % 2 == 1) return e[m];
  return 0.5 * (e[m] + *std::max_element(e.begin(), e.begin() + static_cast<long>(m)));
}

double KeypointGroup::mean_px() const {
  if (errors_px.empty()) return kNaN;
  return std::accumulate(errors_px.begin(), errors_px.end(), 0.0) / errors_px.size();
}

double KeypointGroup::pck_torso(int i) const {
  return ratio(within_torso.at(i), keypoints);
}

double KeypointGroup::pck_height(int i) const {
  return ratio(within_height.at(i), keypoints);
}

double KeypointGroup::swap_rate() const {
  return ratio(swapped, pairs);
}

void KeypointGroup::add(const KeypointGroup& o) {
  keypoints += o.keypoints;
  detected += o.detected;
  for (size_t i = 0; i < within_torso.size(); ++i) within_torso[i] += o.within_torso[i];
  for (size_t i = 0; i < within_height.size(); ++i) within_height[i] += o.within_height[i];
  errors_px.insert(errors_px.end(), o.errors_px.begin(), o.errors_px.end());
  pairs += o.pairs;
  swapped += o.swapped;
}

KeypointScores score_keypoints(const KeypointTruth& truth, const Detections& detections,
                               const KeypointScoreOptions& options) {
  const KeypointLayout& layout = keypoint_layout(truth.layout());
  if (options.actor < 0 || options.actor >= static_cast<int>(truth.actors().size())) {
    throw Error("2D scores: no actor " + std::to_string(options.actor));
  }
  KeypointScores s;
  s.layout = truth.layout();
  s.actor = truth.actors()[options.actor];
  s.min_keypoint_score = options.min_keypoint_score;
  s.coco = coco_keypoint_ap(truth, detections);
  s.per_keypoint.resize(static_cast<size_t>(layout.size()));
  const int ls = hanim_index(layout, "l_shoulder"), rs = hanim_index(layout, "r_shoulder"),
            lh = hanim_index(layout, "l_hip"), rh = hanim_index(layout, "r_hip");
  const int cameras = static_cast<int>(truth.cameras().size());
  for (int f = 0; f < truth.frames(); ++f) {
    for (int c = 0; c < cameras; ++c) {
      const ActorView& view = truth.at(f, c, options.actor);
      if (!view.annotated) continue;
      ++s.images;
      const auto& people = detections.at(f, c);
      const DetectedPerson* chosen = nullptr;
      double best = kMinMatchOks;
      for (const DetectedPerson& p : people) {
        const double oks = keypoint_oks(view, p, layout).value_or(0.0);
        if (oks > best || (!chosen && oks >= best)) {
          best = oks;
          chosen = &p;
        }
      }
      if (people.empty()) ++s.no_person;
      if (!people.empty() && !chosen) ++s.unmatched;
      if (people.size() == 1) ++s.one_person;
      if (people.size() > 1) {
        ++s.several_people;
        const double top =
            std::max_element(people.begin(), people.end(), [](const auto& a, const auto& b) {
              return a.score < b.score;
            })->score;
        s.several_chosen_top += chosen && chosen->score >= top;
      }
      const auto& t = view.keypoints;
      const auto truth_px = [&](int k) {
        return k >= 0 && t[k].known ? t[k].pixel : Eigen::Vector2d::Constant(kNaN);
      };
      const double torso =
          0.5 * ((truth_px(ls) - truth_px(rh)).norm() + (truth_px(rs) - truth_px(lh)).norm());
      const auto detected = [&](int k) {
        return chosen && chosen->keypoints[k].score > options.min_keypoint_score;
      };
      for (int k = 0; k < layout.size(); ++k) {
        if (!t[k].known) continue;
        const int v = static_cast<int>(t[k].visibility);
        KeypointGroup& g = s.per_keypoint[k][v];
        ++g.keypoints;
        if (!detected(k)) continue;
        ++g.detected;
        const double e = (pixel_of(chosen->keypoints[k]) - t[k].pixel).norm();
        g.errors_px.push_back(e);
        for (size_t i = 0; i < kTorsoFractions.size(); ++i)
          g.within_torso[i] += e <= kTorsoFractions[i] * torso;
        for (size_t i = 0; i < kHeightFractions.size(); ++i) {
          g.within_height[i] += e <= kHeightFractions[i] * view.box_height;
        }
        const int p = layout.keypoints[k].partner;
        const auto in_frame = [&](int i) {
          return t[i].known && t[i].visibility != VisibilityLabel::out_of_frame;
        };
        if (p < 0 || !in_frame(k) || !in_frame(p) || !detected(p)) continue;
        const Eigen::Vector2d dk = pixel_of(chosen->keypoints[k]),
                              dp = pixel_of(chosen->keypoints[p]);
        const bool swapped = (dk - t[p].pixel).norm() + (dp - t[k].pixel).norm() <
                             (dk - t[k].pixel).norm() + (dp - t[p].pixel).norm();
        ++g.pairs;
        g.swapped += swapped;
        if (k < p) {
          ++s.swap_pairs;
          s.swapped_pairs += swapped;
        }
      }
    }
  }
  for (const auto& classes : s.per_keypoint) {
    for (int v = 0; v < kVisibilityClasses; ++v) {
      s.by_visibility[v].add(classes[v]);
      if (v != static_cast<int>(VisibilityLabel::out_of_frame)) s.all.add(classes[v]);
    }
  }
  return s;
}

}  // namespace simcap
