// Fuzz target: joint limits from URDF (read_urdf_limits through urdfdom) for the default humanoid.
#include "models/humanoid.h"
#include "models/urdf_io.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const simcap::Skeleton humanoid = simcap::build_humanoid();
  const auto path = simcap::fuzz::write_input("limits.urdf", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_urdf_limits(path, humanoid); });
  return 0;
}
