// What the articulated fit registers the stick model to on one frame: Moschini's centerline
// points, plus the cues simcap adds (hull containment, silhouette rays and outlines).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "tracker/moschini/silhouette_view.h"
#include "tracker/moschini/stick_model.h"
#include "tracker/moschini/visual_hull.h"

namespace simcap::tracker {

constexpr std::uint16_t kAllParts = (1u << kSegmentCount) - 1;

struct SilhouetteRay {
  Eigen::Vector3d origin;                // the camera centre
  Eigen::Vector3d direction;             // unit, world
  std::array<std::uint8_t, 3> colour{};  // the pixel's colour, when the frame's were read
  std::uint16_t parts = kAllParts;       // the sticks it may meet (bit s = Segment s)
  int camera = -1;                       // the camera and pixel it goes through
  int u = 0, v = 0;
};

struct IcpTargets {
  std::vector<Eigen::Vector3d> points;  // centerline points (Moschini §3.2)
  // When set, the sticks are kept inside the hull: a limb whose slices merge with the torso or
  // with the other limb yields no centerline points, and data-to-model matching alone lets it
  // wander off through empty space to explain a few stray points.
  const Occupancy* hull = nullptr;
  // Rays from each camera through a grid of its silhouette pixels: every one must meet the body.
  // Unlike the hull, they carry no phantom volume (the parts of the hull that no
  // camera can see empty), so they are what finally places the limbs.
  std::vector<SilhouetteRay> rays;
  // The silhouettes themselves: the capsules' outlines must project inside each of them.
  const std::vector<SilhouetteView>* views = nullptr;
  // Where the motion model expects the body (the previous estimate): when set, the fit pays
  // for moving away from it (RefineOptions::motion_prior_m_per_rad), also when hypotheses are
  // compared, so that a limb does not jump to another place that explains the data as well.
  const StickPose* prediction = nullptr;
};

// Closest point on any stick's centerline: the clamped projection onto each (Fig. 4.3-4.4).
struct ClosestStick {
  int segment = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  // the closest point, on the stick
  // The model point paired with the data point. Inside the stick it is `point`; past a joint end
  // it is the foot of the perpendicular on the stick's line, because data beyond a joint belong
  // to the next segment (or to a part the model lacks, like the feet or the crotch between
  // merged legs) and must not drag this stick along its own axis. Only past a free tip (head
  // top, finger tips) is it the tip itself, which fixes how far a chain reaches.
  Eigen::Vector3d match = Eigen::Vector3d::Zero();
  bool on_line = false;  // `match` is a perpendicular foot: only the distance across counts
  double along = 0;      // position of `point` on the stick: 0 proximal, 1 distal
  double distance = 0;
};
ClosestStick closest_stick(const StickGeometry& g, const Eigen::Vector3d& x);

// The point of `ray` nearest to the segment [a, b], by alternating clamped projections: exact
// unless the ray starts within the segment's reach, which a camera's centre never does. (Inline:
// the fitting calls it for every ray and capsule it tries.)
inline Eigen::Vector3d nearest_on_ray(const SilhouetteRay& ray, const Eigen::Vector3d& a,
                                      const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d& u = ray.direction;
  const Eigen::Vector3d w = ray.origin - a;
  const double aa = ab.squaredNorm(), au = ab.dot(u), aw = ab.dot(w), uw = u.dot(w);
  const double den = aa - au * au;
  const double t_lines = den > 1e-12 ? std::clamp((aw - au * uw) / den, 0.0, 1.0) : 0.0;
  auto on_ray = [&](double t) {
    return ray.origin + std::max(0.0, (a + t * ab - ray.origin).dot(u)) * u;
  };
  const double t = std::clamp((on_ray(t_lines) - a).dot(ab) / aa, 0.0, 1.0);
  return on_ray(t);
}

// The X84 threshold on distances: med + k · 1.4826 · med|e - med|, but never below `floor`:
// near convergence on clean data the MAD shrinks towards 0 and X84 would reject the very points
// that still pull a limb into place.
double x84_threshold(std::vector<double> distances, double k, double floor);

}  // namespace simcap::tracker
