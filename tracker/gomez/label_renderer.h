// The body's colour cells rendered for one pose hypothesis into a small image: each capsule is
// projected as a 2D tapered capsule (its ends' discs of radius f r / z) with a z-buffer, inside a
// crop around the person at a reduced resolution, so hundreds of hypotheses a frame are cheap.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core/types.hpp>
#include <vector>

#include "core/camera.h"
#include "tracker/gomez/body_shape.h"

namespace simcap::tracker::gomez {

inline constexpr std::uint8_t kNoCell = 255;

// Where the working image lies in the camera's image: working pixel (u, v) covers the
// full-resolution pixels [x0 + k u, x0 + k (u + 1)) x [y0 + k v, y0 + k (v + 1)), k = factor.
struct View {
  const Camera* camera = nullptr;
  int x0 = 0, y0 = 0;
  int factor = 1;
  int width = 0, height = 0;

  // Working-image coordinates (pixel centres at integers) of a full-resolution pixel.
  Eigen::Vector2d to_working(const Eigen::Vector2d& pixel) const {
    return (pixel - Eigen::Vector2d(x0, y0) + Eigen::Vector2d::Constant(0.5)) / factor -
           Eigen::Vector2d::Constant(0.5);
  }
};

struct LabelImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> cell;      // colour cell per pixel (capsule * kCellsPerCapsule + cell)
  std::vector<float> depth;            // camera z of the front surface, metres
  int u0 = 0, u1 = 0, v0 = 0, v1 = 0;  // pixels drawn lie in [u0, u1) x [v0, v1)

  std::uint8_t at(int u, int v) const { return cell[v * width + u]; }
};

// Renders `shape` posed by `joint_world` (forward_kinematics of the pose) into `out`, resized to
// the view. Capsules with an end closer than 5 cm to the camera plane are left out.
void render_labels(const BodyShape& shape, const std::vector<Eigen::Isometry3d>& joint_world,
                   const View& view, LabelImage& out);

// Full-resolution extent of the posed capsules in the camera's image (not clipped to it), in
// pixel coordinates; empty when every capsule is behind the camera.
Eigen::AlignedBox2d body_extent(const BodyShape& shape,
                                const std::vector<Eigen::Isometry3d>& joint_world,
                                const Camera& camera);
// body_extent in whole pixels.
cv::Rect body_box(const BodyShape& shape, const std::vector<Eigen::Isometry3d>& joint_world,
                  const Camera& camera);

}  // namespace simcap::tracker::gomez
