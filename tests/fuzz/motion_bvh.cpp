// Fuzz target: a BVH file as a scene's motion: read, retargeted to the default humanoid and
// resampled to 30 frames/s (load_motion), which is where a clip's frame time sets the work.
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const simcap::Skeleton humanoid = simcap::build_humanoid();
  simcap::MotionSource source;
  source.bvh = simcap::fuzz::write_input("clip.bvh", simcap::fuzz::as_text(data, size));
  simcap::fuzz::expect_value_or_error([&] { simcap::load_motion(source, humanoid, 30.0); });
  return 0;
}
