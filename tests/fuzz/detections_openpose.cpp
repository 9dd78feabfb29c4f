// Fuzz target: an OpenPose --write_json folder (read_openpose_folder), the input's parts being
// files of the two cameras' folders, e.g. "==> cam00/000001_keypoints.json <==".
#include "models/detections.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir = simcap::fuzz::write_parts(
      simcap::fuzz::as_text(data, size),
      {"cam00/000000_keypoints.json", "cam00/000001_keypoints.json", "cam01/000000_keypoints.json",
       "cam01/video_000000000002_keypoints.json", "cam01/000009_keypoints.json"});
  simcap::fuzz::expect_value_or_error([&] {
    simcap::read_openpose_folder(dir, {"cam00", "cam01"}, 3);
  });
  return 0;
}
