// Fuzz target: the ground truth `simcap validate --detections` reads (read_keypoint_truth, for a
// layout with H-Anim joints and COCO points and one with Human3.6M points): the input's parts are
// the dataset's files, e.g. "==> gt/keypoints_coco.json <==".
#include "validate/keypoint_truth.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir =
      simcap::fuzz::write_parts(simcap::fuzz::as_text(data, size),
                                {"calibration/opencv.yaml", "scene.yaml", "gt/keypoints_coco.json",
                                 "gt/joints2d.csv", "gt/joints3d_h36m17.csv"});
  for (const auto layout : {simcap::KeypointLayoutId::coco17, simcap::KeypointLayoutId::body25}) {
    simcap::fuzz::expect_value_or_error([&] { simcap::read_keypoint_truth(dir, layout); });
  }
  return 0;
}
