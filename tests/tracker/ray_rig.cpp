#include "tests/tracker/ray_rig.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/camera.h"

namespace simcap::testing {

using namespace simcap::tracker;

double segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b) {
  const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  return (x - a - t * (b - a)).norm();
}

namespace {

// Where the ray enters the capsule [a, b] of radius r: its distance to the segment is convex
// along the ray, so bisection between the camera and the closest approach finds the entry.
double entry_depth(const SilhouetteRay& ray, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                   double r) {
  const Eigen::Vector3d q = nearest_on_ray(ray, a, b);
  if (segment_distance(q, a, b) > r) return std::numeric_limits<double>::infinity();
  double lo = 0, hi = (q - ray.origin).dot(ray.direction);
  for (int i = 0; i < 50; ++i) {
    const double mid = 0.5 * (lo + hi);
    (segment_distance(ray.origin + mid * ray.direction, a, b) > r ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace

std::vector<double> camera_ring(int cameras) {
  std::vector<double> azimuths;
  for (int c = 0; c < cameras; ++c) azimuths.push_back(2 * std::numbers::pi * c / cameras + 0.3);
  return azimuths;
}

std::vector<SilhouetteRay> silhouette_rays(const StickModel& model, const StickPose& pose,
                                           int stride, const Palette* palette,
                                           std::vector<int>* shown,
                                           const std::vector<double>& azimuths) {
  const StickGeometry g = model.geometry(pose);
  const BodyDimensions& dims = model.dimensions();
  std::vector<SilhouetteRay> rays;
  if (shown) shown->clear();
  for (const double angle : azimuths) {
    const Eigen::Vector3d eye =
        pose.t0 + Eigen::Vector3d(4 * std::sin(angle), 1.0, 4 * std::cos(angle));
    const Camera cam = Camera::look_at("c", 320, 480, 0.7, eye, pose.t0);
    for (int v = 0; v < cam.height; v += stride) {
      for (int x = 0; x < cam.width; x += stride) {
        SilhouetteRay ray{cam.centre(), cam.unproject(Eigen::Vector2d(x, v))};
        int front = -1;
        double front_depth = std::numeric_limits<double>::infinity();
        for (int s = 0; s < kSegmentCount; ++s) {
          const double depth =
              entry_depth(ray, g.line_proximal[s], g.line_distal[s], dims.radius[s]);
          if (depth < front_depth) front = s, front_depth = depth;
        }
        if (front < 0) continue;
        if (palette) {
          // Shading scales all channels alike: brighter where the surface faces up.
          const Eigen::Vector3d p = ray.origin + front_depth * ray.direction;
          const Eigen::Vector3d ab = g.line_distal[front] - g.line_proximal[front];
          const double t =
              std::clamp((p - g.line_proximal[front]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
          const Eigen::Vector3d normal = (p - g.line_proximal[front] - t * ab).normalized();
          const double shade = 0.75 + 0.25 * normal.y();
          for (int k = 0; k < 3; ++k) {
            ray.colour[k] = static_cast<std::uint8_t>(std::lround(shade * (*palette)[front][k]));
          }
        }
        rays.push_back(ray);
        if (shown) shown->push_back(front);
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
