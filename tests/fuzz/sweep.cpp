// Fuzz target: a stress sweep file (load_sweep) and its expansion into runs (sweep_points). The
// sweep's folder also holds scene.yaml and clip.bvh, so that `scene:` and `motion:` can name
// existing files (the sweep reader only checks that they exist).
#include <fstream>

#include "tests/fuzz/fuzz_input.h"
#include "validate/sweep_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("sweep.yaml", simcap::fuzz::as_text(data, size));
  for (const char* name : {"scene.yaml", "clip.bvh"}) std::ofstream(path.parent_path() / name);
  simcap::fuzz::expect_value_or_error([&] { simcap::sweep_points(simcap::load_sweep(path)); });
  return 0;
}
