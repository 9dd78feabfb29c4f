// Fuzz target: an H-Anim X3D humanoid as an actor's body (parse_x3d_humanoid through pugixml:
// joint tree, skin and weights, then finish_imported_body's checks).
#include "models/x3d_humanoid.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  simcap::fuzz::expect_value_or_error(
      [&] { simcap::parse_x3d_humanoid(simcap::fuzz::as_text(data, size), "fuzz.x3d"); });
  return 0;
}
