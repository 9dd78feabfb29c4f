// Fuzz target: the detections CSV (read_detections_csv) for a dataset of three cameras and five
// frames, the layout inferred from the keypoint names.
#include "models/detections.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = simcap::fuzz::write_input("det.csv", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] {
    simcap::read_detections_csv(path, {"cam00", "cam01", "cam02"}, 5);
  });
  return 0;
}
