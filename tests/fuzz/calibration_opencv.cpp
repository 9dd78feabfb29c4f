// Fuzz target: calibration/opencv.yaml (read_opencv_calibration: OpenCV FileStorage YAML).
#include "core/calibration.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("opencv.yaml", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::read_opencv_calibration(path); });
  return 0;
}
