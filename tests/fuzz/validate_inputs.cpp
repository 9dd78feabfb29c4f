// Fuzz target: what `simcap validate DATASET TRACK` reads (load_validation_inputs): the input's
// parts are the dataset's and the track's files, e.g. "==> track/joints3d.csv <==".
#include "tests/fuzz/fuzz_input.h"
#include "validate/validation_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir = simcap::fuzz::write_parts(
      simcap::fuzz::as_text(data, size),
      {"dataset/scene.yaml", "dataset/calibration/opencv.yaml", "dataset/gt/joints3d.csv",
       "dataset/gt/joints2d.csv", "dataset/gt/angles.csv", "track/joints3d.csv",
       "track/angles.csv"});
  simcap::fuzz::expect_value_or_error(
      [&] { simcap::load_validation_inputs(dir / "dataset", dir / "track"); });
  return 0;
}
