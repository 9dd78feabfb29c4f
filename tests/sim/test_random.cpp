// The counter-based random numbers: a hash continued with more keys equals the hash of the whole
// tuple (the renderer hashes (seed, stream, camera, frame) once per image and continues it per
// pixel), and the whole tuple matters.
#include <gtest/gtest.h>

#include "sim/random.h"

namespace simcap {
namespace {

TEST(RandomBits, ContinuedHashEqualsWholeTuple) {
  for (std::uint64_t seed : {0ull, 1ull, 0xdeadbeefull}) {
    for (std::uint64_t pixel = 0; pixel < 1000; pixel += 37) {
      const std::uint64_t whole = random_bits(seed, {1, 2, 3, pixel, 5});
      EXPECT_EQ(random_bits_after(random_bits(seed, {1, 2, 3}), {pixel, 5}), whole);
      EXPECT_EQ(random_bits_after(random_bits(seed, {1}), {2, 3, pixel, 5}), whole);
      EXPECT_EQ(random_bits_after(random_bits(seed, {1, 2, 3, pixel, 5}), {}), whole);
      EXPECT_NE(random_bits(seed, {1, 2, 3, pixel, 6}), whole);
      EXPECT_NE(random_bits(seed + 1, {1, 2, 3, pixel, 5}), whole);
    }
  }
  // Keys are ordered: swapping two changes the value.
  EXPECT_NE(random_bits(7, {1, 2}), random_bits(7, {2, 1}));
}

}  // namespace
}  // namespace simcap
