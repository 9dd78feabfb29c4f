#include "sim/camera_rays.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

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

Eigen::Vector3f CameraRays::jittered_ray(int x, int y, float jx, float jy) const {
  const int w1 = camera_.width + 1;
  const size_t c = static_cast<size_t>(y) * w1 + x;
  const float ax = jx + 0.5f, ay = jy + 0.5f;
  const Eigen::Vector2f xy = (1 - ay) * ((1 - ax) * corners_[c] + ax * corners_[c + 1]) +
                             ay * ((1 - ax) * corners_[c + w1] + ax * corners_[c + w1 + 1]);
  return camera_to_world_ * Eigen::Vector3f(xy.x(), xy.y(), 1.f);
}

Eigen::Vector3f CameraRays::jittered_direction(int x, int y, float jx, float jy) const {
  return jittered_ray(x, y, jx, jy).normalized();
}

void CameraRays::jittered_block(int px, int py, const float* jx, const float* jy, const int* valid,
                                float* dir_x, float* dir_y, float* dir_z) const {
  // jittered_ray() lane by lane, in structure-of-arrays form so that the arithmetic vectorises:
  // the corner loads are gathered first, then every operation runs in jittered_ray's order
  // (Eigen sums a 3-term product as a0 + (a1 + a2)), bit for bit.
  const int w1 = camera_.width + 1;
  alignas(64) float x00[kLanes], y00[kLanes], x01[kLanes], y01[kLanes];
  alignas(64) float x10[kLanes], y10[kLanes], x11[kLanes], y11[kLanes];
  auto gather = [&](int k, const Eigen::Vector2f* c) {
    x00[k] = c[0].x();
    y00[k] = c[0].y();
    x01[k] = c[1].x();
    y01[k] = c[1].y();
    x10[k] = c[w1].x();
    y10[k] = c[w1].y();
    x11[k] = c[w1 + 1].x();
    y11[k] = c[w1 + 1].y();
  };
  const Eigen::Vector2f* first = corners_.data() + static_cast<size_t>(py) * w1 + px;
  int whole = -1;
  for (int k = 0; k < kLanes; ++k) whole &= valid[k];
  if (whole) {
    // Row by row: the corners of a row of the block are contiguous.
    for (int r = 0; r < kBlock; ++r) {
      for (int x = 0; x < kBlock; ++x) gather(r * kBlock + x, first + r * w1 + x);
    }
  } else {
    // Lanes outside the image read pixel (px, py)'s corners and are overwritten below.
    for (int k = 0; k < kLanes; ++k) {
      gather(k, first + (valid[k] ? (k / kBlock) * w1 + k % kBlock : 0));
    }
  }
  // Inputs, matrix and results in locals: stores through the output pointers could alias the
  // others, which kept the loop scalar.
  const Eigen::Matrix3f m = camera_to_world_;
  const float m00 = m(0, 0), m01 = m(0, 1), m02 = m(0, 2), m10 = m(1, 0), m11 = m(1, 1);
  const float m12 = m(1, 2), m20 = m(2, 0), m21 = m(2, 1), m22 = m(2, 2);
  alignas(64) float ox[kLanes], oy[kLanes], oz[kLanes], jitter_x[kLanes], jitter_y[kLanes];
  alignas(64) int inside[kLanes];
  std::copy_n(jx, kLanes, jitter_x);
  std::copy_n(jy, kLanes, jitter_y);
  std::copy_n(valid, kLanes, inside);
  for (int k = 0; k < kLanes; ++k) {
    const float ax = jitter_x[k] + 0.5f, ay = jitter_y[k] + 0.5f;
    const float x =
        (1 - ay) * ((1 - ax) * x00[k] + ax * x01[k]) + ay * ((1 - ax) * x10[k] + ax * x11[k]);
    const float y =
        (1 - ay) * ((1 - ax) * y00[k] + ax * y01[k]) + ay * ((1 - ax) * y10[k] + ax * y11[k]);
    const bool in = inside[k] != 0;
    ox[k] = in ? m00 * x + (m01 * y + m02) : 0.f;
    oy[k] = in ? m10 * x + (m11 * y + m12) : 0.f;
    oz[k] = in ? m20 * x + (m21 * y + m22) : 1.f;
  }
  std::copy_n(ox, kLanes, dir_x);
  std::copy_n(oy, kLanes, dir_y);
  std::copy_n(oz, kLanes, dir_z);
}

}  // namespace simcap
