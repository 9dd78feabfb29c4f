#include "sim/srgb.h"

#include <algorithm>
#include <cmath>

#include "sim/avx2_clones.h"

namespace simcap {

float srgb_to_linear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

Eigen::Vector3f srgb_to_linear(const Eigen::Vector3f& c) {
  return {srgb_to_linear(c.x()), srgb_to_linear(c.y()), srgb_to_linear(c.z())};
}

float linear_to_srgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.f / 2.4f) - 0.055f;
}

SrgbEncoder::SrgbEncoder() {
  for (std::uint32_t i = 0; i < kSize; ++i) {
    const float s = linear_to_srgb(static_cast<float>(i) / (kSize - 1));
    table_[i] = static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.f, 1.f) * 255.f));
  }
}

SIMCAP_AVX2_CLONES void SrgbEncoder::encode(const float* linear, std::uint8_t* codes) const {
  std::uint32_t indices[kBatch];
  for (int i = 0; i < kBatch; ++i) indices[i] = index(linear[i]);
  for (int i = 0; i < kBatch; ++i) codes[i] = table_[indices[i]];
}

}  // namespace simcap
