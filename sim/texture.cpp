#include "sim/texture.h"

#include <cmath>

#include "core/error.h"
#include "core/image_io.h"
#include "sim/srgb.h"

namespace simcap {

Texture::Texture(const std::filesystem::path& file) {
  const cv::Mat image = read_image(file);
  const int channels = image.channels();
  if (!(image.depth() == CV_8U || image.depth() == CV_16U) || channels == 2 || channels > 4) {
    throw Error(file.string() + ": texture must be an 8- or 16-bit grey, RGB or RGBA image");
  }
  cv::Mat unit;
  image.convertTo(unit, CV_32F, image.depth() == CV_8U ? 1.0 / 255 : 1.0 / 65535);
  width_ = unit.cols;
  height_ = unit.rows;
  texels_.resize(static_cast<size_t>(width_) * height_);
  for (int y = 0; y < height_; ++y) {
    const float* row = unit.ptr<float>(y);
    for (int x = 0; x < width_; ++x) {
      const float* px = row + x * channels;
      const Eigen::Vector3f srgb =
          channels == 1 ? Eigen::Vector3f::Constant(px[0]) : Eigen::Vector3f(px[0], px[1], px[2]);
      texels_[static_cast<size_t>(y) * width_ + x] = srgb_to_linear(srgb);
    }
  }
}

Eigen::Vector3f Texture::sample(float u, float v) const {
  // Texel centres sit at half-texel offsets; wrap both neighbours of the sample point.
  const float x = (u - std::floor(u)) * width_ - 0.5f;
  const float y = (v - std::floor(v)) * height_ - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  auto wrap = [](int i, int n) { return ((i % n) + n) % n; };
  const int x0 = wrap(static_cast<int>(fx), width_), x1 = wrap(x0 + 1, width_);
  const int y0 = wrap(static_cast<int>(fy), height_), y1 = wrap(y0 + 1, height_);
  auto at = [&](int xi, int yi) -> const Eigen::Vector3f& {
    return texels_[static_cast<size_t>(yi) * width_ + xi];
  };
  return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x1, y0)) +
         ay * ((1 - ax) * at(x0, y1) + ax * at(x1, y1));
}

}  // namespace simcap
