// Fuzz target: EasyMocap's calibration pair (read_easymocap_calibration); the input holds
// "==> intri.yml <==" and "==> extri.yml <==" parts.
#include "core/calibration.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir =
      simcap::fuzz::write_parts(simcap::fuzz::as_text(data, size), {"intri.yml", "extri.yml"});
  simcap::fuzz::expect_value_or_error(
      [&] { simcap::read_easymocap_calibration(dir / "intri.yml", dir / "extri.yml"); });
  return 0;
}
