// Fuzz target: the frame,joint,x,y,z table (read_joint_track: gt/joints3d.csv, TRACK/joints3d.csv).
#include "core/joint_track.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("joints3d.csv", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_joint_track(path); });
  return 0;
}
