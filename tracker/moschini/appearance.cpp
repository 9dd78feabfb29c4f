#include "tracker/moschini/appearance.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <opencv2/core.hpp>
#include <optional>

namespace simcap::tracker {
namespace {

// Left and right limbs are dressed alike; the kinds of part that may differ in colour.
constexpr int kKinds = 9;
constexpr std::array<int, kSegmentCount> kKindOf = {0, 1, 2, 3, 4, 5, 3, 4, 5, 6, 7, 8, 6, 7, 8};

// Chromaticity: the share of two channels in the brightness, which shading leaves alone (a
// thigh in the light and a calf in the shade wear the same trousers); none for dark pixels.
std::optional<Eigen::Vector2d> chromaticity(const Eigen::Vector3d& colour, double min_sum) {
  const double sum = colour.sum();
  if (sum < min_sum) return std::nullopt;
  return Eigen::Vector2d(colour(0), colour(1)) / sum;
}

// The part a ray shows: that of the front-most capsule it passes, if it passes that one well
// inside.
int shown_part(const PlacedSurface& surface, const SilhouetteRay& ray, double inside_fraction) {
  int front = -1;
  double front_depth = std::numeric_limits<double>::infinity(), front_d = 0, front_reach = 0;
  for (int c = 0; c < kCapsuleCount; ++c) {
    const PlacedCapsule& capsule = surface[c];
    const Eigen::Vector3d q = nearest_on_ray(ray, capsule.a, capsule.a + capsule.ab);
    double d;
    Eigen::Vector3d dir;
    if (!capsule.distance(q, &d, &dir) || d > 0.02) continue;
    const double reach = capsule.radius(capsule.along(q));
    // Where the ray enters the capsule, for a circular section of radius `reach`.
    const double axis = std::max(0.0, reach + d);
    const double depth =
        (q - ray.origin).dot(ray.direction) - std::sqrt(std::max(0.0, reach * reach - axis * axis));
    if (depth < front_depth) front = c, front_depth = depth, front_d = d, front_reach = reach;
  }
  return front >= 0 && front_d < -inside_fraction * front_reach ? surface[front].segment : -1;
}

// The materials the body is dressed in (shirt, skin, trousers...): OpenCV's k-means on all
// chromaticities, with more clusters until each is compact. Clusters start from quantiles of the
// first channel's share, so that the result does not depend on a random seed.
template <typename Material>
std::vector<Material> materials(const std::vector<Eigen::Vector2d>& colours,
                                std::vector<int>& label, const AppearanceOptions& options) {
  const int n = static_cast<int>(colours.size());
  cv::Mat samples(n, 2, CV_32F);
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < 2; ++c) samples.at<float>(i, c) = static_cast<float>(colours[i](c));
  }
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return colours[a](0) < colours[b](0); });
  std::vector<Material> out;
  const double floor2 = options.noise_floor * options.noise_floor;
  for (int k = 1; k <= options.max_materials && k <= n; ++k) {
    cv::Mat labels(n, 1, CV_32S);
    for (int r = 0; r < n; ++r) labels.at<int>(order[r]) = r * k / n;
    cv::Mat centres;
    cv::kmeans(samples, k, labels,
               cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 1e-5), 1,
               cv::KMEANS_USE_INITIAL_LABELS, centres);
    out.clear();
    bool compact = true;
    for (int cluster = 0; cluster < k; ++cluster) {
      Eigen::Vector2d sum = Eigen::Vector2d::Zero();
      Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
      int count = 0;
      for (int i = 0; i < n; ++i) {
        if (labels.at<int>(i) != cluster) continue;
        sum += colours[i];
        outer += colours[i] * colours[i].transpose();
        ++count;
      }
      const Eigen::Vector2d mean = sum / std::max(count, 1);
      const Eigen::Matrix2d cov = outer / std::max(count, 1) - mean * mean.transpose();
      if (count >= options.min_samples && cov.diagonal().maxCoeff() > floor2) compact = false;
      out.push_back({mean, (cov + floor2 * Eigen::Matrix2d::Identity()).inverse()});
    }
    label.assign(labels.begin<int>(), labels.end<int>());
    if (compact) break;
  }
  return out;
}

}  // namespace

AppearanceModel::AppearanceModel() : table_(1 << 15, kAllParts) {}

AppearanceModel::AppearanceModel(const StickModel& model, const BodySurface& surface,
                                 const StickPose& pose, const std::vector<SilhouetteRay>& rays,
                                 const AppearanceOptions& options)
    : AppearanceModel() {
  const PlacedSurface placed = place(surface, model.geometry(pose));
  std::array<std::vector<Eigen::Vector2d>, kKinds> colours;
  for (const SilhouetteRay& ray : rays) {
    const int s = shown_part(placed, ray, options.inside_fraction);
    const auto c = chromaticity(Eigen::Vector3d(ray.colour[0], ray.colour[1], ray.colour[2]),
                                options.min_brightness);
    if (s >= 0 && c) colours[kKindOf[s]].push_back(*c);
  }
  std::vector<Eigen::Vector2d> all;
  std::vector<int> kind_of_sample;
  for (int k = 0; k < kKinds; ++k) {
    all.insert(all.end(), colours[k].begin(), colours[k].end());
    kind_of_sample.insert(kind_of_sample.end(), colours[k].size(), k);
  }
  std::vector<int> material_of;
  if (!all.empty()) dress_ = materials<Material>(all, material_of, options);
  const std::vector<Material>& dress = dress_;
  // Each kind of part wears the materials that make up a fair share of its samples.
  std::vector<std::uint16_t> wearers(dress.size(), 0);
  std::uint16_t unknown = 0;  // parts whose kind has no colour model: never excluded
  for (int k = 0; k < kKinds; ++k) {
    std::uint16_t segments = 0;
    for (int s = 0; s < kSegmentCount; ++s) {
      if (kKindOf[s] == k) segments |= 1u << s;
    }
    const int n = static_cast<int>(colours[k].size());
    if (n < options.min_samples) {
      unknown |= segments;
      continue;
    }
    ++learned_;
    std::vector<int> count(dress.size(), 0);
    for (size_t i = 0; i < all.size(); ++i) {
      if (kind_of_sample[i] == k) ++count[material_of[i]];
    }
    for (size_t m = 0; m < dress.size(); ++m) {
      if (count[m] >= options.min_share * n) wearers[m] |= segments;
    }
  }
  if (!dress.empty()) foreign_.assign(table_.size(), 0), distinct_.assign(table_.size(), 0);
  for (int code = 0; code < (1 << 15); ++code) {
    const auto c = chromaticity(
        Eigen::Vector3d((code >> 10) * 8 + 4, ((code >> 5) & 31) * 8 + 4, (code & 31) * 8 + 4),
        options.min_brightness);
    std::uint16_t parts = 0;
    bool worn = false;
    for (size_t m = 0; c && m < dress.size(); ++m) {
      if (dress[m].distance2(*c) > options.max_distance2) continue;
      parts |= wearers[m];
      worn = true;
    }
    table_[code] = parts ? parts | unknown : kAllParts;
    // A material of the person's own rays is the person's even when the parts wearing it were
    // seen by too few rays to tell (the skin of the hands and the face on a first frame where
    // some views are left out because someone else touches the person there).
    if (c && !dress.empty() && !worn) foreign_[code] = 1;
    if (worn) distinct_[code] = 1;
  }
}

void AppearanceModel::learn_others(const std::vector<std::array<std::uint8_t, 3>>& colours,
                                   const AppearanceOptions& options) {
  if (dress_.empty()) return;
  std::vector<Eigen::Vector2d> samples;
  for (const auto& colour : colours) {
    if (const auto c =
            chromaticity(Eigen::Vector3d(colour[0], colour[1], colour[2]), options.min_brightness))
      samples.push_back(*c);
  }
  if (static_cast<int>(samples.size()) < options.min_samples) return;
  std::vector<int> material_of;
  const std::vector<Material> all = materials<Material>(samples, material_of, options);
  // Only their main materials: the gate's cut leaves a few of the person's own pixels among
  // theirs.
  std::vector<Material> theirs;
  for (size_t m = 0; m < all.size(); ++m) {
    const auto n = std::count(material_of.begin(), material_of.end(), static_cast<int>(m));
    if (n >= options.min_share * static_cast<double>(samples.size())) theirs.push_back(all[m]);
  }
  for (int code = 0; code < (1 << 15); ++code) {
    const auto c = chromaticity(
        Eigen::Vector3d((code >> 10) * 8 + 4, ((code >> 5) & 31) * 8 + 4, (code & 31) * 8 + 4),
        options.min_brightness);
    if (!c) continue;
    double own = std::numeric_limits<double>::infinity();
    for (const Material& m : dress_) own = std::min(own, m.distance2(*c));
    for (const Material& m : theirs) {
      if (m.distance2(*c) < std::min(own, options.max_distance2)) foreign_[code] = 1;
      if (m.distance2(*c) <= options.max_distance2) distinct_[code] = 0;
    }
  }
}

}  // namespace simcap::tracker
