// Test support: silhouette rays of a capsule body seen by a ring of six cameras, optionally
// coloured by the part each pixel shows, and a walking pose to look at. The capsules are traced
// exactly (round cones), not with the tracker's own distance.
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "tracker/moschini/body_surface.h"
#include "tracker/moschini/icp_targets.h"
#include "tracker/moschini/perception.h"
#include "tracker/moschini/stick_model.h"

namespace simcap::testing {

// BGR colour of each part (Segment order).
using Palette = std::array<std::array<std::uint8_t, 3>, tracker::kSegmentCount>;

// Where the cameras stand: azimuths around the torso, 4 m away and 1 m above it.
std::vector<double> camera_ring(int cameras = 6);
// The camera at `azimuth` looking at the torso of `pose` (320 x 480 pixels).
Camera ring_camera(const tracker::StickPose& pose, double azimuth);

// The rays through every pixel (on a `stride` pixel grid) that sees the capsules of `surface` on
// `pose`. With a palette, each ray carries the colour of the part whose capsule it meets first,
// shaded by a light from above (factor 0.5–1), and `shown` gets that part (a Segment).
std::vector<tracker::SilhouetteRay> silhouette_rays(
    const tracker::StickModel& model, const tracker::BodySurface& surface,
    const tracker::StickPose& pose, int stride, const Palette* palette = nullptr,
    std::vector<int>* shown = nullptr, const std::vector<double>& azimuths = camera_ring());

// Each ring camera's silhouette of the capsules (255 where a pixel's ray meets one).
std::vector<cv::Mat> silhouette_masks(const tracker::StickModel& model,
                                      const tracker::BodySurface& surface,
                                      const tracker::StickPose& pose,
                                      const std::vector<double>& azimuths = camera_ring());

// What the tracker observes of the capsules on `pose` from the ring cameras at `azimuths`: the
// hull carved in `volume` (2 cm voxels), its centerline, rays on a 4-pixel grid, the silhouette
// views. The views point at `cameras`: keep the whole rig alive while `observation` is in use.
struct RigObservation {
  std::vector<Camera> cameras;
  tracker::Observation observation;
};
RigObservation observe_rig(const tracker::StickModel& model, const tracker::BodySurface& surface,
                           const tracker::StickPose& pose, const std::vector<double>& azimuths,
                           const Eigen::AlignedBox3d& volume);

// The same, with the centerline of `centerline_pose` in place of the pose's own: silhouettes
// that show one pose and a hull centerline that leads the refinement to another.
RigObservation observe_rig_misled(const tracker::StickModel& model,
                                  const tracker::BodySurface& surface,
                                  const tracker::StickPose& pose,
                                  const tracker::StickPose& centerline_pose,
                                  const std::vector<double>& azimuths,
                                  const Eigen::AlignedBox3d& volume);

// Distance from x to the segment [a, b].
double segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a,
                        const Eigen::Vector3d& b);

// Torso turned, arms swinging, one knee bent.
tracker::StickPose walking_pose();

}  // namespace simcap::testing
