#include "tracker/moschini/perception.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <numeric>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

Perception::Perception(const Dataset& dataset, SilhouetteMethod method,
                       const PerceptionOptions& options)
    : dataset_(&dataset),
      options_(options),
      silhouettes_(dataset, method, options.silhouettes),
      hull_(dataset.cameras(), options.hull),
      gate_(dataset.cameras(), options.gate) {
  const int stride = options_.ray_stride;
  if (stride <= 0) return;
  for (const Camera& cam : dataset.cameras()) {
    std::vector<Eigen::Vector3f>& table = ray_directions_.emplace_back();
    for (int v = stride / 2; v < cam.height; v += stride) {
      for (int u = stride / 2; u < cam.width; u += stride) {
        table.push_back(cam.unproject(Eigen::Vector2d(u, v)).cast<float>());
      }
    }
  }
}

cv::Mat Perception::foreign_pixels(cv::Mat& silhouette, const cv::Mat& colour,
                                   cv::Mat& distinct) const {
  cv::Mat foreign = cv::Mat::zeros(silhouette.size(), CV_8UC1);
  distinct = cv::Mat::zeros(silhouette.size(), CV_8UC1);
  for (int v = 0; v < silhouette.rows; ++v) {
    std::uint8_t* own = silhouette.ptr<std::uint8_t>(v);
    std::uint8_t* out = foreign.ptr<std::uint8_t>(v);
    std::uint8_t* alone = distinct.ptr<std::uint8_t>(v);
    const cv::Vec3b* rgb = colour.ptr<cv::Vec3b>(v);
    for (int u = 0; u < silhouette.cols; ++u) {
      if (!own[u]) continue;
      const std::array<std::uint8_t, 3> c{rgb[u][0], rgb[u][1], rgb[u][2]};
      if (appearance_.foreign(c))
        own[u] = 0, out[u] = 255;
      else if (appearance_.distinct(c))
        alone[u] = 255;
    }
  }
  return foreign;
}

Observation Perception::observe(int frame, bool compare_masks) const {
  using Clock = std::chrono::steady_clock;
  Observation obs;
  obs.frame = frame;
  const int nc = dataset_->camera_count();
  std::vector<cv::Mat> silhouettes(nc), colours(nc), cover(nc), distinct(nc);
  if (compare_masks) obs.silhouette_iou.assign(nc, 0.0);
  auto t = Clock::now();
  const bool others = dataset_->actors().size() > 1;
  const bool gt = silhouettes_.method() == SilhouetteMethod::gt;
  // Background subtraction sees everyone: with others about, the pixels in colours the person
  // does not wear are someone else's, who may hide the person there (cover) but whose rays
  // must not pull the body.
  const bool split = others && !gt && options_.colours && appearance_.learned_parts() > 0;
  tbb::parallel_for(0, nc, [&](int c) {
    silhouettes[c] =
        silhouettes_.extract(c, frame, options_.colours ? &colours[c] : nullptr, !split);
    if (gt && others) cover[c] = dataset_->others(c, frame);
    if (split) cover[c] = foreign_pixels(silhouettes[c], colours[c], distinct[c]);
    if (compare_masks)
      obs.silhouette_iou[c] = silhouette_iou(silhouettes[c], dataset_->mask(c, frame));
  });
  const int stride = options_.ray_stride;
  for (int c = 0; stride > 0 && c < nc; ++c) {
    const Camera& cam = dataset_->cameras()[c];
    const Eigen::Vector3d origin = cam.centre();
    size_t i = 0;
    for (int v = stride / 2; v < cam.height; v += stride) {
      const std::uint8_t* row = silhouettes[c].ptr<std::uint8_t>(v);
      const cv::Vec3b* rgb = options_.colours ? colours[c].ptr<cv::Vec3b>(v) : nullptr;
      for (int u = stride / 2; u < cam.width; u += stride, ++i) {
        if (!row[u]) continue;
        SilhouetteRay& ray =
            obs.rays.emplace_back(origin, ray_directions_[c][i].cast<double>().normalized());
        ray.camera = c;
        ray.u = u;
        ray.v = v;
        if (rgb) {
          ray.colour = {rgb[u][0], rgb[u][1], rgb[u][2]};
          ray.parts = appearance_.parts(ray.colour);
        }
      }
    }
  }
  obs.silhouettes_ms = ms_since(t);
  obs.silhouettes = std::move(silhouettes);
  if (others && (gt || split)) obs.cover = std::move(cover);
  if (split) obs.distinct = std::move(distinct);
  shape(obs.silhouettes, obs);
  return obs;
}

void Perception::keep_rays_in_silhouettes(Observation& obs) {
  std::erase_if(obs.rays, [&](const SilhouetteRay& r) {
    return !obs.silhouettes[r.camera].at<std::uint8_t>(r.v, r.u);
  });
}

void Perception::shape(const std::vector<cv::Mat>& given, Observation& obs) const {
  using Clock = std::chrono::steady_clock;
  auto t = Clock::now();
  std::vector<cv::Mat> covered, own;
  if (!obs.cover.empty()) {
    for (size_t c = 0; c < given.size(); ++c) covered.push_back(given[c] | obs.cover[c]);
  }
  if (!obs.abstains.empty()) {
    // An abstaining camera's silhouette, with or without the cover, is the whole image.
    own = given;
    for (size_t c = 0; c < given.size(); ++c) {
      if (!obs.abstains[c]) continue;
      own[c] = cv::Mat(given[c].size(), CV_8UC1, cv::Scalar(255));
      if (!covered.empty()) covered[c] = own[c];
    }
  }
  const std::vector<cv::Mat>& sources = own.empty() ? given : own;
  const std::vector<cv::Mat>& silhouettes = covered.empty() ? sources : covered;
  obs.views.clear();
  if (options_.views) {
    for (size_t c = 0; c < silhouettes.size(); ++c) {
      obs.views.emplace_back(dataset_->cameras()[c], silhouettes[c]);
    }
  }
  obs.silhouettes_ms += ms_since(t);
  t = Clock::now();
  hull_.carve(silhouettes, obs.hull);
  obs.hull_ms += ms_since(t);
  t = Clock::now();
  // With cover, the hull holds the others' volume next to the person too (the gate keeps what
  // lies within reach), and its slices' centroids would pull the limbs into them: the
  // centerline comes from the person's own pixels. A limb hidden behind someone loses its
  // centerline points there but keeps the outline views and the hull's containment.
  if (covered.empty()) {
    obs.centerline = centerline(obs.hull, options_.skeleton);
  } else {
    Occupancy own_hull;
    hull_.carve(sources, own_hull);
    obs.centerline = centerline(own_hull, options_.skeleton);
  }
  obs.points.clear();
  obs.points.reserve(obs.centerline.size());
  for (const CenterlinePoint& p : obs.centerline) obs.points.push_back(p.position);
  obs.centerline_ms += ms_since(t);
}

GateResult Perception::isolate(Observation& obs, const PlacedSurface& body,
                               std::vector<cv::Mat>* dropped,
                               const std::vector<Eigen::Vector3d>* others_before) const {
  std::vector<cv::Mat> before;
  if (dropped) {
    for (const cv::Mat& s : obs.silhouettes) before.push_back(s.clone());
  }
  obs.gate =
      gate_.restrict(obs.hull, body, obs.silhouettes, &obs.cover, &obs.distinct, others_before);
  const GateResult& result = obs.gate;
  if (dropped) {
    dropped->clear();
    for (size_t c = 0; c < before.size(); ++c) dropped->push_back(before[c] & ~obs.silhouettes[c]);
  }
  if (!result.changed) return result;
  keep_rays_in_silhouettes(obs);
  shape(obs.silhouettes, obs);
  return result;
}

void Perception::point_at_person(Observation& obs, int reach_px) const {
  const size_t nc = obs.silhouettes.size();
  obs.cover.resize(nc);
  const cv::Mat reach =
      cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * reach_px + 1, 2 * reach_px + 1});
  for (size_t c = 0; c < nc; ++c) {
    cv::Mat near;
    cv::dilate(dataset_->mask(static_cast<int>(c), obs.frame), near, reach);
    cv::Mat& silhouette = obs.silhouettes[c];
    const cv::Mat others = silhouette & ~near;
    obs.cover[c] = obs.cover[c].empty() ? others : (obs.cover[c] | others);
    silhouette &= near;
  }
  keep_rays_in_silhouettes(obs);
  shape(obs.silhouettes, obs);
}

void Perception::abstain_until_seen(Observation& obs) const {
  const int nc = static_cast<int>(obs.silhouettes.size());
  std::vector<int> order(nc);
  std::iota(order.begin(), order.end(), 0);
  std::vector<int> pixels(nc);
  for (int c = 0; c < nc; ++c) pixels[c] = cv::countNonZero(obs.silhouettes[c]);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return pixels[a] < pixels[b]; });
  int abstained = 0;
  for (int c : order) {
    if (obs.hull.count > 0 || nc - abstained <= 2) break;
    obs.abstains.resize(nc, false);
    obs.abstains[c] = true;
    ++abstained;
    shape(obs.silhouettes, obs);
  }
}

std::vector<SilhouetteRay> Perception::rays_apart(const Observation& obs,
                                                  const std::vector<cv::Mat>& dropped) const {
  std::vector<bool> apart(obs.silhouettes.size(), true);
  const cv::Mat near = cv::getStructuringElement(cv::MORPH_ELLIPSE, {7, 7});
  for (size_t c = 0; c < apart.size() && c < dropped.size(); ++c) {
    cv::Mat around;
    cv::dilate(dropped[c], around, near);
    apart[c] = cv::countNonZero(around & obs.silhouettes[c]) == 0;
  }
  if (std::find(apart.begin(), apart.end(), true) == apart.end()) return obs.rays;
  std::vector<SilhouetteRay> rays;
  for (const SilhouetteRay& r : obs.rays) {
    if (apart[r.camera]) rays.push_back(r);
  }
  return rays;
}

std::vector<std::array<std::uint8_t, 3>> Perception::colours_under(
    int frame, const std::vector<cv::Mat>& masks) const {
  std::vector<std::array<std::uint8_t, 3>> out;
  const int stride = std::max(options_.ray_stride, 1);
  for (size_t c = 0; c < masks.size(); ++c) {
    if (cv::countNonZero(masks[c]) == 0) continue;
    const cv::Mat rgb = dataset_->rgb(static_cast<int>(c), frame);
    for (int v = stride / 2; v < masks[c].rows; v += stride) {
      for (int u = stride / 2; u < masks[c].cols; u += stride) {
        if (!masks[c].at<std::uint8_t>(v, u)) continue;
        const cv::Vec3b& p = rgb.at<cv::Vec3b>(v, u);
        out.push_back({p[0], p[1], p[2]});
      }
    }
  }
  return out;
}

void Perception::widen(Observation& obs, const OcclusionMap& occlusion) const {
  std::vector<cv::Mat> wide(obs.silhouettes.size());
  bool changed = false;
  for (size_t c = 0; c < wide.size(); ++c) {
    wide[c] = occlusion.widen(static_cast<int>(c), obs.silhouettes[c]);
    changed = changed || wide[c].data != obs.silhouettes[c].data;
  }
  if (changed) shape(wide, obs);
  obs.widened = changed;
}

}  // namespace simcap::tracker
