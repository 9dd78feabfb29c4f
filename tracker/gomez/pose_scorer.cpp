// Region and edge costs of a pose hypothesis (pose_scorer.h).
#include "tracker/gomez/pose_scorer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "models/pose.h"

namespace simcap::tracker::gomez {

Energy energy(const Score& score, const ScoreOptions& options) {
  const double f = score.region / options.sigma_region, d = score.edge / options.sigma_edge_px;
  const double e = options.sigma_feet_px > 0 ? score.feet / options.sigma_feet_px : 0.0;
  const double t = options.sigma_top_px > 0 ? score.top / options.sigma_top_px : 0.0;
  const double g = options.sigma_shade_grey;
  return {0.5 * f * f, 0.5 * d * d, 0.5 * (e * e + t * t), g > 0 ? 0.5 * score.shade / (g * g) : 0};
}

RegionModel region_model(const BodyShape& shape, const std::vector<std::uint8_t>& cell_class,
                         bool split_head) {
  RegionModel m;
  m.cell_class = cell_class;
  m.head_cell.assign(cell_class.size(), 0);
  std::array<int, kMaxColourClasses + 1> votes{};
  for (size_t c = 0; c < cell_class.size(); ++c) {
    if (shape.capsules[c / kCellsPerCapsule].part != Part::head) continue;
    m.head_cell[c] = 1;
    ++votes[cell_class[c]];
  }
  if (split_head) {
    m.head_class =
        static_cast<int>(std::max_element(votes.begin() + 1, votes.end()) - votes.begin());
    if (votes[m.head_class] == 0) m.head_class = 0;
  }
  return m;
}

bool tells_front_from_back(const BodyShape& shape, const std::vector<std::uint8_t>& cell_class) {
  for (size_t ci = 0; ci < shape.capsules.size(); ++ci) {
    if (shape.capsules[ci].front.squaredNorm() == 0) continue;
    const std::uint8_t* cells = &cell_class[ci * kCellsPerCapsule];
    std::array<int, kMaxColourClasses + 1> votes{};
    for (int k = 0; k < kCellsPerCapsule; ++k) ++votes[cells[k]];
    const int most = static_cast<int>(std::max_element(votes.begin(), votes.end()) - votes.begin());
    if (cells[kCellsPerCapsule - 1] != most) return true;
  }
  return false;
}

double region_cost(const LabelImage& labels, const RegionModel& model, const FrameCues& cues,
                   RegionCombine combine) {
  // Per class: image pixels (A), model pixels (B), both; index 0 holds the head class's share
  // under the model's head (its A is counted here, the rest of the class keeps the remainder).
  std::array<int, kMaxColourClasses + 1> area = cues.class_area, drawn{}, both{};
  std::array<bool, kMaxColourClasses + 1> modelled{};
  for (const std::uint8_t c : model.cell_class) modelled[c] = true;
  const int hc = model.head_class;
  area[0] = 0;
  for (int v = labels.v0; v < labels.v1; ++v) {
    const std::uint8_t* cell = &labels.cell[static_cast<size_t>(v) * labels.width];
    const std::uint8_t* seen = &cues.cls[static_cast<size_t>(v) * labels.width];
    for (int u = labels.u0; u < labels.u1; ++u) {
      if (cell[u] == kNoCell) continue;
      int c = model.cell_class[cell[u]];
      if (hc && model.head_cell[cell[u]]) {
        area[0] += seen[u] == hc;
        if (c == hc) c = 0;
      }
      ++drawn[c];
      both[c] += seen[u] == (c == 0 ? hc : c);
    }
  }
  if (hc) area[hc] -= area[0];
  modelled[0] = hc != 0;
  double sum = 0, non_overlap = 0, union_all = 0;
  int m = 0;
  std::array<double, kMaxColourClasses + 1> ratio{};
  for (int c = 0; c <= kMaxColourClasses; ++c) {
    if (!modelled[c]) continue;
    const double u = area[c] + drawn[c] - both[c];
    if (u <= 0) continue;
    ratio[m++] = (u - both[c]) / u;
    non_overlap += u - both[c];
    union_all += u;
  }
  if (m == 0) return 1.0;
  switch (combine) {
    case RegionCombine::root_sum:
      for (int k = 0; k < m; ++k) sum += std::pow(ratio[k], 1.0 / m);
      return sum / m;
    case RegionCombine::mean:
      for (int k = 0; k < m; ++k) sum += ratio[k];
      return sum / m;
    case RegionCombine::pixels:
      break;
  }
  return non_overlap / union_all;
}

bool on_contour(const LabelImage& labels, int u, int v, double gap_m) {
  const size_t i = static_cast<size_t>(v) * labels.width + u;
  const int capsule = labels.cell[i] / kCellsPerCapsule;
  const float z = labels.depth[i];
  for (const auto& [du, dv] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
    const int x = u + du, y = v + dv;
    if (x < 0 || y < 0 || x >= labels.width || y >= labels.height) return true;
    const size_t k = static_cast<size_t>(y) * labels.width + x;
    if (labels.cell[k] == kNoCell) return true;
    if (labels.cell[k] / kCellsPerCapsule != capsule && labels.depth[k] - z > gap_m) return true;
  }
  return false;
}

double chamfer_cost(const LabelImage& labels, const FrameCues& cues, double gap_m) {
  double sum = 0;
  long count = 0;
  for (int v = labels.v0; v < labels.v1; ++v) {
    for (int u = labels.u0; u < labels.u1; ++u) {
      const size_t i = static_cast<size_t>(v) * labels.width + u;
      if (labels.cell[i] == kNoCell || !on_contour(labels, u, v, gap_m)) continue;
      sum += cues.distance[i];
      ++count;
    }
  }
  return count ? sum / static_cast<double>(count) : cues.far;
}

PoseScorer::PoseScorer(const BodyDofs& dofs, const BodyShape& shape,
                       const std::vector<std::uint8_t>& cell_class, const ScoreOptions& options)
    : dofs_(&dofs),
      shape_(&shape),
      options_(options),
      region_(region_model(shape, cell_class, options.split_head)),
      shading_(shape, dofs.skeleton(), cell_class) {}

void PoseScorer::render(const State& x, const View& view, LabelImage& out) const {
  render_labels(*shape_, forward_kinematics(dofs_->skeleton(), dofs_->pose(x)), view, out);
}

double feet_offset(double model_bottom, const FrameCues& cues) {
  if (!std::isfinite(cues.feet_row) || !std::isfinite(model_bottom)) return 0.0;
  return (model_bottom - cues.feet_row) / cues.view.factor;
}

double top_offset(double model_top, const FrameCues& cues) {
  if (!std::isfinite(cues.top_row) || !std::isfinite(model_top)) return 0.0;
  return (model_top - cues.top_row) / cues.view.factor;
}

Score PoseScorer::score(const State& x, const FrameCues& cues) const {
  thread_local LabelImage labels;
  const auto world = forward_kinematics(dofs_->skeleton(), dofs_->pose(x));
  render_labels(*shape_, world, cues.view, labels);
  Score s{region_cost(labels, region_, cues, options_.combine),
          chamfer_cost(labels, cues, options_.occlusion_gap_m)};
  if (options_.sigma_feet_px > 0 || options_.sigma_top_px > 0) {
    const Eigen::AlignedBox2d box = body_extent(*shape_, world, *cues.view.camera);
    s.feet = feet_offset(box.isEmpty() ? NAN : box.max().y(), cues);
    s.top = top_offset(box.isEmpty() ? NAN : box.min().y(), cues);
  }
  if (options_.sigma_shade_grey > 0 && lighting_.known()) {
    s.shade = flip_penalty(shading_.observe(labels, world, cues), lighting_);
  }
  return s;
}

}  // namespace simcap::tracker::gomez
