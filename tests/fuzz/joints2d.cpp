// Fuzz target: gt/joints2d.csv's per-camera visibility (read_visibility_table), for the cameras
// of the shipped studio4 rig.
#include "tests/fuzz/fuzz_input.h"
#include "validate/visibility.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("joints2d.csv", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] {
    simcap::read_visibility_table(path, {"cam00", "cam01", "cam02", "cam03"});
  });
  return 0;
}
