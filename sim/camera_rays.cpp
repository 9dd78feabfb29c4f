#include "sim/camera_rays.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>

#include "core/error.h"

namespace simcap {

CameraRays::CameraRays(const Camera& camera)
    : camera_(camera),
      origin_(camera.centre().cast<float>()),
      camera_to_world_(camera.R.transpose().cast<float>()) {
  const int w = camera.width, h = camera.height;
  if (w <= 0 || h <= 0) throw Error("camera '" + camera.name + "': image size must be positive");
  blocks_x_ = (w + kBlock - 1) / kBlock;
  const int blocks_y = (h + kBlock - 1) / kBlock;
  data_.assign(static_cast<size_t>(blocks_x_) * blocks_y * kBlockFloats, 0.f);
  corners_.resize(static_cast<size_t>(w + 1) * (h + 1));
  // Rows of whole blocks (padding included) and the h + 1 rows of pixel corners.
  tbb::parallel_for(0, std::max(blocks_y * kBlock, h + 1), [&](int y) {
    for (int x = 0; y < blocks_y * kBlock && x < blocks_x_ * kBlock; ++x) {
      float* b =
          data_.data() + (static_cast<size_t>(y / kBlock) * blocks_x_ + x / kBlock) * kBlockFloats;
      const int lane = (y % kBlock) * kBlock + x % kBlock;
      Eigen::Vector3d d_cam = Eigen::Vector3d::UnitZ();
      if (x < w && y < h) d_cam = camera.unproject_camera({double(x), double(y)});
      const Eigen::Vector3d d = camera.R.transpose() * d_cam;
      b[lane] = static_cast<float>(d.x());
      b[kLanes + lane] = static_cast<float>(d.y());
      b[2 * kLanes + lane] = static_cast<float>(d.z());
      b[3 * kLanes + lane] = static_cast<float>(d_cam.z());
    }
    if (y > h) return;
    for (int x = 0; x <= w; ++x) {
      const Eigen::Vector3d c = camera.unproject_camera({x - 0.5, y - 0.5});
      corners_[static_cast<size_t>(y) * (w + 1) + x] = (c.head<2>() / c.z()).cast<float>();
    }
  });
}

Eigen::Vector3f CameraRays::jittered_direction(int x, int y, float jx, float jy) const {
  const int w1 = camera_.width + 1;
  const size_t c = static_cast<size_t>(y) * w1 + x;
  const float ax = jx + 0.5f, ay = jy + 0.5f;
  const Eigen::Vector2f xy = (1 - ay) * ((1 - ax) * corners_[c] + ax * corners_[c + 1]) +
                             ay * ((1 - ax) * corners_[c + w1] + ax * corners_[c + w1 + 1]);
  return (camera_to_world_ * Eigen::Vector3f(xy.x(), xy.y(), 1.f)).normalized();
}

}  // namespace simcap
