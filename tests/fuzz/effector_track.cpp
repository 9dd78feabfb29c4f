// Fuzz target: the effectors2d.csv table of 2D end-effector tracks (read_effector_track), as
// `simcap track --method sik --effectors depth|mono|multiview` writes it.
#include "core/effector_track.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("effectors2d.csv", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_effector_track(path); });
  return 0;
}
