// The capsules' outlines against a camera's silhouette: points along each capsule's outline as
// the camera sees it, and for those that fall outside, where the silhouette's edge is.
#pragma once

#include <Eigen/Core>
#include <cmath>

#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/silhouette_view.h"

namespace simcap::tracker {

struct RimPoint {
  int capsule = 0;
  double t = 0;                                      // along the capsule's axis
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // on the outline, world
  Eigen::Vector3d radial = Eigen::Vector3d::Zero();  // unit, from the axis to `point`
  // For a point outside the silhouette, the silhouette's edge nearest to its pixel, at the
  // point's own depth: half a pixel short of the nearest silhouette pixel's centre, so that the
  // distance to it grows from zero as the point leaves the silhouette.
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  bool outside = false;
};

// Calls f(const RimPoint&) for the points every `step_m` (at least two per capsule) on both
// sides of every capsule's outline that project into the image.
template <typename F>
void for_each_rim_point(const SilhouetteView& view, const PlacedSurface& surface, double step_m,
                        F&& f) {
  const Camera& cam = view.camera();
  const Eigen::Vector3d centre = cam.centre();
  RimPoint rim;
  for (int c = 0; c < kCapsuleCount; ++c) {
    const PlacedCapsule& capsule = surface[c];
    const Eigen::Vector3d axis = capsule.ab.normalized();
    const int n = std::max(2, static_cast<int>(capsule.ab.norm() / step_m));
    rim.capsule = c;
    for (int i = 0; i < n; ++i) {
      rim.t = (i + 0.5) / n;
      const Eigen::Vector3d x = capsule.a + rim.t * capsule.ab;
      // The outline of a cylinder seen from `centre` runs across both the axis and the view.
      const Eigen::Vector3d across = axis.cross(x - centre).normalized();
      for (const double side : {-1.0, 1.0}) {
        rim.radial = side * across;
        rim.point = x + capsule.radius(rim.t) * rim.radial;
        const Eigen::Vector3d pc = cam.to_camera(rim.point);
        if (pc.z() <= 0) continue;
        const Eigen::Vector2d px = cam.project_camera(pc);
        // Nearest pixel; std::lround is a library call, and this loop runs a thousand times per
        // evaluation.
        const int u = static_cast<int>(std::floor(px.x() + 0.5)),
                  v = static_cast<int>(std::floor(px.y() + 0.5));
        if (u < 0 || v < 0 || u >= cam.width || v >= cam.height) continue;
        rim.outside = !view.inside(u, v);
        if (rim.outside) {
          const Eigen::Vector2d near = view.nearest(u, v).cast<double>();
          const double d = (px - near).norm();
          const Eigen::Vector2d edge =
              d > 0.5 ? Eigen::Vector2d(near + (px - near) * (0.5 / d)) : px;
          const Eigen::Vector3d dir = cam.unproject_camera(edge);
          rim.target = cam.to_world(dir * (pc.z() / dir.z()));
        }
        f(rim);
      }
    }
  }
}

}  // namespace simcap::tracker
