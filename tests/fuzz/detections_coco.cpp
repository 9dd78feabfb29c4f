// Fuzz target: COCO keypoint results JSON (read_coco_results) for a dataset of three cameras and
// five frames.
#include "models/detections.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("det.json", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] {
    simcap::read_coco_results(path, {"cam00", "cam01", "cam02"}, 5);
  });
  return 0;
}
