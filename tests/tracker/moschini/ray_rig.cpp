#include "tests/tracker/moschini/ray_rig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/camera.h"
#include "tracker/moschini/skeletonize.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::testing {

using namespace simcap::tracker;

double segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (x - a - t * (b - a)).norm();
}

namespace {

// The least value of f on [lo, hi] for f unimodal there (golden-section search).
template <typename F>
double least(F&& f, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 40; ++i) {
    const double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    if (f(m1) < f(m2)) {
      hi = m2;
    } else {
      lo = m1;
    }
  }
  return std::min({f(lo), f(hi), f(0.5 * (lo + hi))});
}

// Where the ray enters the round cone of `c` (the union of the spheres swept along its axis with
// the radius changing linearly), or infinity: the least entry depth into those spheres, sampled
// along the axis, then refined by golden section around the best sample.
double entry_depth(const SilhouetteRay& ray, const PlacedCapsule& c) {
  auto sphere_entry = [&](double t) {
    const Eigen::Vector3d to_centre = c.a + t * c.ab - ray.origin;
    const double along = to_centre.dot(ray.direction), r = c.radius(t);
    const double h = r * r - (to_centre.squaredNorm() - along * along);
    return h < 0 ? std::numeric_limits<double>::infinity() : along - std::sqrt(h);
  };
  constexpr int kSamples = 256;
  int best = 0;
  for (int i = 1; i <= kSamples; ++i) {
    if (sphere_entry(static_cast<double>(i) / kSamples) <
        sphere_entry(static_cast<double>(best) / kSamples)) {
      best = i;
    }
  }
  return std::min(sphere_entry(static_cast<double>(best) / kSamples),
                  least(sphere_entry, std::max(0, best - 1) / static_cast<double>(kSamples),
                        std::min(kSamples, best + 1) / static_cast<double>(kSamples)));
}

// Whether the ray meets the round cone of `c`: the distance from the ray's line to the axis
// point less the radius there is convex along the axis, so a golden-section search finds its
// least value.
bool hits(const SilhouetteRay& ray, const PlacedCapsule& c) {
  auto f = [&](double t) {
    const Eigen::Vector3d v = c.a + t * c.ab - ray.origin;
    return (v - v.dot(ray.direction) * ray.direction).norm() - c.radius(t);
  };
  return least(f, 0.0, 1.0) <= 0;
}

}  // namespace

std::vector<double> camera_ring(int cameras) {
  std::vector<double> azimuths;
  for (int c = 0; c < cameras; ++c) azimuths.push_back(2 * std::numbers::pi * c / cameras + 0.3);
  return azimuths;
}

Camera ring_camera(const StickPose& pose, double azimuth) {
  const Eigen::Vector3d eye =
      pose.t0 + Eigen::Vector3d(4 * std::sin(azimuth), 1.0, 4 * std::cos(azimuth));
  return Camera::look_at("c", 320, 480, 0.7, eye, pose.t0);
}

std::vector<cv::Mat> silhouette_masks(const StickModel& model, const BodySurface& surface,
                                      const StickPose& pose, const std::vector<double>& azimuths) {
  const PlacedSurface placed = place(surface, model.geometry(pose));
  std::vector<cv::Mat> masks;
  for (const double azimuth : azimuths) {
    const Camera cam = ring_camera(pose, azimuth);
    cv::Mat mask = cv::Mat::zeros(cam.height, cam.width, CV_8U);
    for (int v = 0; v < cam.height; ++v) {
      for (int u = 0; u < cam.width; ++u) {
        const SilhouetteRay ray{cam.centre(), cam.unproject(Eigen::Vector2d(u, v))};
        for (const PlacedCapsule& c : placed) {
          if ((c.centre - ray.origin).cross(ray.direction).norm() <= c.bound && hits(ray, c)) {
            mask.at<std::uint8_t>(v, u) = 255;
            break;
          }
        }
      }
    }
    masks.push_back(mask);
  }
  return masks;
}

RigObservation observe_rig(const StickModel& model, const BodySurface& surface,
                           const StickPose& pose, const std::vector<double>& azimuths,
                           const Eigen::AlignedBox3d& volume) {
  RigObservation rig;
  for (const double a : azimuths) rig.cameras.push_back(ring_camera(pose, a));
  const std::vector<cv::Mat> masks = silhouette_masks(model, surface, pose, azimuths);
  Observation& obs = rig.observation;
  HullOptions hull;
  hull.volume = volume;
  VisualHull(rig.cameras, hull).carve(masks, obs.hull);
  for (const CenterlinePoint& p : centerline(obs.hull, {})) obs.points.push_back(p.position);
  obs.rays = silhouette_rays(model, surface, pose, 4, nullptr, nullptr, azimuths);
  for (size_t c = 0; c < rig.cameras.size(); ++c) obs.views.emplace_back(rig.cameras[c], masks[c]);
  return rig;
}

RigObservation observe_rig_misled(const StickModel& model, const BodySurface& surface,
                                  const StickPose& pose, const StickPose& centerline_pose,
                                  const std::vector<double>& azimuths,
                                  const Eigen::AlignedBox3d& volume) {
  RigObservation rig = observe_rig(model, surface, pose, azimuths, volume);
  rig.observation.points =
      observe_rig(model, surface, centerline_pose, azimuths, volume).observation.points;
  return rig;
}

std::vector<SilhouetteRay> silhouette_rays(const StickModel& model, const BodySurface& surface,
                                           const StickPose& pose, int stride,
                                           const Palette* palette, std::vector<int>* shown,
                                           const std::vector<double>& azimuths) {
  const PlacedSurface placed = place(surface, model.geometry(pose));
  std::vector<SilhouetteRay> rays;
  if (shown) shown->clear();
  for (size_t k = 0; k < azimuths.size(); ++k) {
    const Camera cam = ring_camera(pose, azimuths[k]);
    for (int v = 0; v < cam.height; v += stride) {
      for (int x = 0; x < cam.width; x += stride) {
        SilhouetteRay ray{cam.centre(), cam.unproject(Eigen::Vector2d(x, v))};
        ray.camera = static_cast<int>(k), ray.u = x, ray.v = v;
        int front = -1;
        double front_depth = std::numeric_limits<double>::infinity();
        for (int c = 0; c < kCapsuleCount; ++c) {
          // Only capsules the ray passes near need the exact test.
          if ((placed[c].centre - ray.origin).cross(ray.direction).norm() > placed[c].bound) {
            continue;
          }
          const double depth = entry_depth(ray, placed[c]);
          if (depth < front_depth) front = c, front_depth = depth;
        }
        if (front < 0) continue;
        const int part = placed[front].segment;
        if (palette) {
          // Shading scales all channels alike: brighter where the surface faces up.
          const PlacedCapsule& c = placed[front];
          const Eigen::Vector3d p = ray.origin + front_depth * ray.direction;
          const Eigen::Vector3d normal = (p - c.a - c.along(p) * c.ab).normalized();
          const double shade = 0.75 + 0.25 * normal.y();
          for (int k = 0; k < 3; ++k) {
            ray.colour[k] = static_cast<std::uint8_t>(std::lround(shade * (*palette)[part][k]));
          }
        }
        rays.push_back(ray);
        if (shown) shown->push_back(part);
      }
    }
  }
  return rays;
}

StickPose walking_pose() {
  StickPose p;
  p.t0 = {0.2, 1.1, -0.1};
  p.R0 = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()).toRotationMatrix();
  p.theta[kLShoulder1] = 0.5;
  p.theta[kRShoulder1] = -0.5;
  p.theta[kLElbow] = -0.6;
  p.theta[kLHip2] = -0.4;
  p.theta[kRHip2] = 0.3;
  p.theta[kRKnee] = 0.5;
  return p;
}

}  // namespace simcap::testing
