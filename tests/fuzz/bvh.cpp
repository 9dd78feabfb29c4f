// Fuzz target: BVH text (parse_bvh, as `simcap motion` and scenes read clips) and the clip's
// forward kinematics at its first and last frame.
#include "models/bvh.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  simcap::fuzz::expect_value_or_error([&] {
    const simcap::BvhClip clip = simcap::parse_bvh(simcap::fuzz::as_text(data, size), "fuzz.bvh");
    simcap::bvh_joint_positions(clip, 0);
    simcap::bvh_joint_positions(clip, clip.frame_count() - 1);
  });
  return 0;
}
