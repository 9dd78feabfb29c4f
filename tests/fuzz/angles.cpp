// Fuzz target: the frame,joint,qw,qx,qy,qz table (read_angle_track: gt/angles.csv,
// TRACK/angles.csv).
#include "core/angle_track.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("angles.csv", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_angle_track(path); });
  return 0;
}
