// sRGB transfer curve: scene colours and textures are sRGB, shading happens in linear light, and
// images are stored as 8-bit sRGB through a table fast enough for millions of pixels a second.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>

namespace simcap {

float srgb_to_linear(float srgb);
Eigen::Vector3f srgb_to_linear(const Eigen::Vector3f& srgb);
float linear_to_srgb(float linear);

// Linear [0, 1] -> 8-bit sRGB code, rounded to nearest. The table has 2^16 entries, so no
// code is ever more than one level away from the exact pow() result.
class SrgbEncoder {
 public:
  SrgbEncoder();
  std::uint8_t operator()(float linear) const { return table_[index(linear)]; }
  // kBatch values at once; out of line, where the table indices' loop vectorises.
  static constexpr int kBatch = 48;
  void encode(const float* linear, std::uint8_t* codes) const;

 private:
  static constexpr std::uint32_t kSize = 1u << 16;
  static std::uint32_t index(float linear) {
    const float clamped = std::min(1.f, std::max(0.f, linear));
    return static_cast<std::uint32_t>(static_cast<int>(clamped * (kSize - 1) + 0.5f));
  }
  std::array<std::uint8_t, kSize> table_;
};

}  // namespace simcap
