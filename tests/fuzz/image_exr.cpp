// Fuzz target: EXR (depth maps) through the project's image I/O (read_image, OpenImageIO).
#include "core/image_io.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("depth.exr", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_image(path); });
  return 0;
}
