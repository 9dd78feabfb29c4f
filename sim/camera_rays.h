// The primary rays of one camera, computed once from the camera model (Camera::unproject), so
// that lens distortion is rendered exactly per pixel and costs nothing per frame. Stored in
// 4x4-pixel blocks laid out as Embree's 16-ray packets, so a packet loads four cache lines.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/camera.h"

namespace simcap {

class CameraRays {
 public:
  // Pixels per side of a block, pixels per block, and floats per block (x, y, z of the
  // direction and the z-scale, each as kLanes consecutive floats).
  static constexpr int kBlock = 4;
  static constexpr int kLanes = kBlock * kBlock;
  static constexpr int kBlockFloats = 4 * kLanes;

  explicit CameraRays(const Camera& camera);

  const Camera& camera() const { return camera_; }
  int width() const { return camera_.width; }
  int height() const { return camera_.height; }
  const Eigen::Vector3f& origin() const { return origin_; }

  // Unit world direction of the ray through the centre of pixel (x, y), and the z component of
  // that direction in camera coordinates (z-depth = distance along the ray * z_scale).
  Eigen::Vector3f direction(int x, int y) const {
    const float* b = block(x / kBlock, y / kBlock);
    const int lane = (y % kBlock) * kBlock + x % kBlock;
    return {b[lane], b[kLanes + lane], b[2 * kLanes + lane]};
  }
  float z_scale(int x, int y) const {
    return block(x / kBlock, y / kBlock)[3 * kLanes + (y % kBlock) * kBlock + x % kBlock];
  }
  // The block of pixels [4 bx, 4 bx + 4) x [4 by, 4 by + 4): 16 direction x, 16 y, 16 z and 16
  // z-scales, lanes in row-major order. Lanes outside the image hold the optical axis.
  const float* block(int bx, int by) const {
    return data_.data() + (static_cast<size_t>(by) * blocks_x_ + bx) * kBlockFloats;
  }
  // Unit world direction through (x + jx, y + jy) with jx, jy in [-0.5, 0.5] (anti-aliasing
  // samples), interpolated bilinearly between the undistorted pixel corners.
  Eigen::Vector3f jittered_direction(int x, int y, float jx, float jy) const;
  // The world direction through (x + jx, y + jy), not normalised (its camera z is 1).
  Eigen::Vector3f jittered_ray(int x, int y, float jx, float jy) const;
  // jittered_ray for the 16 pixels of the block at (px, py), lanes as in block(), bit-identical
  // lane by lane and vectorised: Embree takes directions of any length, and normalising cost as
  // much as the rest. Lanes where `valid` is 0 get (0, 0, 1).
  void jittered_block(int px, int py, const float* jx, const float* jy, const int* valid,
                      float* dir_x, float* dir_y, float* dir_z) const;

 private:
  Camera camera_;
  Eigen::Vector3f origin_;
  Eigen::Matrix3f camera_to_world_;
  int blocks_x_ = 0;
  std::vector<float> data_;
  // Undistorted normalized coordinates (x/z, y/z) at the (width+1) x (height+1) pixel corners.
  std::vector<Eigen::Vector2f> corners_;
};

}  // namespace simcap
