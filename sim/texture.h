// An image tiled over a surface (the room's floor or walls): decoded once from sRGB to linear
// RGB, sampled bilinearly with wrap-around at texture coordinates in metres (one tile per metre).
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <vector>

namespace simcap {

class Texture {
 public:
  // Reads an 8- or 16-bit grey, RGB or RGBA image; throws Error naming the file otherwise.
  explicit Texture(const std::filesystem::path& file);
  // Linear RGB at (u, v) metres; the image's top-left corner sits at (0, 0) and it repeats.
  Eigen::Vector3f sample(float u, float v) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<Eigen::Vector3f> texels_;  // linear RGB, row-major
};

}  // namespace simcap
