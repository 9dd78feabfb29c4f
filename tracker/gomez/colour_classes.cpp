// Learning and applying the colour classes (colour_classes.h).
#include "tracker/gomez/colour_classes.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace simcap::tracker::gomez {
namespace {

// Chromaticity (two channels over the sum) and log brightness: shading on a matte cloth changes
// the brightness much more than the chromaticity, so the Gaussian stretches along one axis.
Eigen::Vector3d feature(double c0, double c1, double c2) {
  const double sum = c0 + c1 + c2 + 3.0;
  return {(c0 + 1.0) / sum, (c1 + 1.0) / sum, std::log(sum / 3.0)};
}

// Sufficient statistics of a Gaussian.
struct Moments {
  double n = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
  Eigen::Vector3d colour = Eigen::Vector3d::Zero();

  void add(const Eigen::Vector3d& f, const Eigen::Vector3d& c) {
    n += 1;
    sum += f;
    outer += f * f.transpose();
    colour += c;
  }
  void add(const Moments& m) {
    n += m.n;
    sum += m.sum;
    outer += m.outer;
    colour += m.colour;
  }
  Eigen::Vector3d mean() const { return sum / n; }
  // Standard deviation of the chromaticity (the first two features), without any floor.
  double chroma_spread() const {
    const Eigen::Vector3d m = mean();
    const Eigen::Matrix3d cov = outer / n - m * m.transpose();
    return std::sqrt(std::max(0.0, 0.5 * (cov(0, 0) + cov(1, 1))));
  }
  Eigen::Matrix3d inverse_covariance(const ColourOptions& o) const {
    const Eigen::Vector3d m = mean();
    Eigen::Matrix3d cov = outer / n - m * m.transpose();
    const double c2 = o.chroma_floor * o.chroma_floor, b2 = o.brightness_floor * o.brightness_floor;
    cov += Eigen::Vector3d(c2, c2, b2).asDiagonal();
    return cov.inverse();
  }
};

}  // namespace

ColourClasses::ColourClasses(const cv::Mat& image, const cv::Mat& silhouette,
                             const LabelImage& cells, const View& view, const BodyShape& shape,
                             const ColourOptions& options) {
  const int cell_count = shape.cell_count();
  if (view.factor != 1) throw Error("colour classes: learn at full resolution (factor 1)");
  std::vector<Moments> cell(cell_count);
  for (int v = 1; v + 1 < cells.height; ++v) {
    for (int u = 1; u + 1 < cells.width; ++u) {
      const std::uint8_t c = cells.at(u, v);
      if (c == kNoCell) continue;
      // Interior pixels of one capsule only: edges mix colours (anti-aliasing, the model's
      // misfit), and another capsule's cell boundary is just as uncertain.
      const int capsule = c / kCellsPerCapsule;
      bool interior = true;
      for (const auto& [du, dv] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const std::uint8_t n = cells.at(u + du, v + dv);
        interior = interior && n != kNoCell && n / kCellsPerCapsule == capsule;
      }
      const int x = view.x0 + u, y = view.y0 + v;
      if (!interior || x < 0 || y < 0 || x >= image.cols || y >= image.rows) continue;
      if (!silhouette.at<std::uint8_t>(y, x)) continue;
      const cv::Vec3b p = image.at<cv::Vec3b>(y, x);
      cell[c].add(feature(p[0], p[1], p[2]), Eigen::Vector3d(p[0], p[1], p[2]));
    }
  }
  // Agglomerate cells into classes, most-sampled cells first.
  std::vector<int> order(cell_count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return cell[a].n > cell[b].n; });
  std::vector<Moments> classes;
  std::vector<int> of(cell_count, -1);
  for (const int c : order) {
    if (cell[c].n < options.min_samples) break;
    int best = -1;
    double best_d2 = INFINITY;
    for (size_t k = 0; k < classes.size(); ++k) {
      const Eigen::Vector3d d = cell[c].mean() - classes[k].mean();
      const double d2 = d.dot(classes[k].inverse_covariance(options) * d);
      if (d2 < best_d2) {
        best_d2 = d2;
        best = static_cast<int>(k);
      }
    }
    const bool pure = cell[c].chroma_spread() < options.pure_chroma;
    if (best_d2 >= options.merge_distance2 && pure &&
        static_cast<int>(classes.size()) < kMaxColourClasses) {
      best = static_cast<int>(classes.size());
      best_d2 = 0;
      classes.emplace_back();
    }
    if (best < 0) continue;  // a mixed cell before any class: it takes a neighbour's below
    if (best_d2 >= options.merge_distance2) {
      of[c] = best;  // a mixed cell (or one colour too many) joins the nearest class, unlearned
      continue;
    }
    classes[best].add(cell[c]);
    of[c] = best;
  }
  if (classes.empty()) {
    throw Error("colour classes: no part of the body shows " + std::to_string(options.min_samples) +
                " pixels inside the silhouette on the first frame");
  }
  // A cell seen too little takes the class of the same cell of the other side's twin, else of
  // the nearest taught cell of its capsule or of the twin, else the first (most seen) class.
  const auto taught_in = [&](int capsule, int k) {
    for (int d = 0; d < kCellsPerCapsule; ++d) {
      for (const int s : {k - d, k + d}) {
        if (s >= 0 && s < kCellsPerCapsule && of[capsule * kCellsPerCapsule + s] >= 0) {
          return of[capsule * kCellsPerCapsule + s];
        }
      }
    }
    return -1;
  };
  cell_class_.assign(cell_count, 1);
  for (int c = 0; c < cell_count; ++c) {
    const int capsule = c / kCellsPerCapsule, k = c % kCellsPerCapsule;
    const int twin = shape.capsules[capsule].mirror;
    int cls = of[c];
    if (cls < 0 && twin >= 0) cls = of[twin * kCellsPerCapsule + k];
    if (cls < 0) cls = taught_in(capsule, k);
    if (cls < 0 && twin >= 0) cls = taught_in(twin, k);
    cell_class_[c] = static_cast<std::uint8_t>(1 + std::max(cls, 0));
  }
  count_ = static_cast<int>(classes.size());
  std::vector<Eigen::Vector3d> means;
  std::vector<Eigen::Matrix3d> inverses;
  for (const Moments& m : classes) {
    means.push_back(m.mean());
    inverses.push_back(m.inverse_covariance(options));
    colour_.push_back(m.colour / m.n);
  }
  lut_.assign(32 * 32 * 32, 0);
  for (int i = 0; i < 32 * 32 * 32; ++i) {
    const Eigen::Vector3d f =
        feature(((i >> 10) & 31) * 8 + 4, ((i >> 5) & 31) * 8 + 4, (i & 31) * 8 + 4);
    double best = options.accept_distance2;
    for (int k = 0; k < count_; ++k) {
      const Eigen::Vector3d d = f - means[k];
      const double d2 = d.dot(inverses[k] * d);
      if (d2 < best) {
        best = d2;
        lut_[i] = static_cast<std::uint8_t>(k + 1);
      }
    }
  }
}

ColourClasses ColourClasses::uniform(int cell_count) {
  ColourClasses c;
  c.count_ = 1;
  c.cell_class_.assign(cell_count, 1);
  c.lut_.assign(32 * 32 * 32, 1);
  c.colour_ = {Eigen::Vector3d::Constant(128)};
  return c;
}

}  // namespace simcap::tracker::gomez
