// Counter-based random numbers: every value is a pure function of (seed, indices), so images
// rendered in parallel, in any tile order, or resumed half-way are identical for the same seed.
#pragma once

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace simcap {

// SplitMix64 finaliser (Steele, Lea & Flood 2014): a bijective 64-bit mix with full avalanche.
inline std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Continues a tuple's hash with more keys: random_bits(seed, {a, b, c}) equals
// random_bits_after(random_bits(seed, {a, b}), {c}), so that keys shared by many values (stream,
// camera, frame) are hashed once rather than for every pixel.
inline std::uint64_t random_bits_after(std::uint64_t state,
                                       std::initializer_list<std::uint64_t> keys) {
  for (const std::uint64_t k : keys) state = mix64(state ^ k);
  return state;
}

// A random 64-bit value for the tuple (seed, keys...).
inline std::uint64_t random_bits(std::uint64_t seed, std::initializer_list<std::uint64_t> keys) {
  return random_bits_after(mix64(seed), keys);
}

// A key for a name, so that a stream follows the name rather than a position in some list.
inline std::uint64_t text_key(std::string_view text) {
  std::uint64_t h = mix64(text.size());
  for (const char c : text) h = mix64(h ^ static_cast<unsigned char>(c));
  return h;
}

// Uniform in [0, 1) from the top 24 bits (exact in float).
inline float uniform01(std::uint64_t bits) {
  return static_cast<float>(bits >> 40) * (1.0f / 16777216.0f);
}

// Standard normal by Box-Muller from the two 32-bit halves of `bits`.
inline float standard_normal(std::uint64_t bits) {
  const float u1 = (static_cast<float>(bits >> 40) + 1.0f) * (1.0f / 16777217.0f);
  const float u2 = static_cast<float>((bits >> 8) & 0xffffffu) * (1.0f / 16777216.0f);
  return std::sqrt(-2.0f * std::log(u1)) * std::cos(6.28318530718f * u2);
}

}  // namespace simcap
