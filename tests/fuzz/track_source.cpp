// Fuzz target: a track's TRACK/dataset.txt checked against a dataset's scene.yaml and
// calibration (check_track_source), as `simcap validate` and `simcap gestures` check it.
#include "core/track_source.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir = simcap::fuzz::write_parts(
      simcap::fuzz::as_text(data, size),
      {"dataset/scene.yaml", "dataset/calibration/opencv.yaml", "track/dataset.txt"});
  simcap::fuzz::expect_value_or_error(
      [&] { simcap::check_track_source(dir / "dataset", dir / "track"); });
  return 0;
}
