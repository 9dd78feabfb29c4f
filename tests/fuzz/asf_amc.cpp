// Fuzz target: an Acclaim ASF/AMC pair as a scene's motion (load_motion: read_asf_amc,
// retargeted to the default humanoid, resampled to 30 frames/s); the input holds
// "==> clip.asf <==" and "==> clip.amc <==" parts.
#include "models/humanoid.h"
#include "models/motion_source.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const simcap::Skeleton humanoid = simcap::build_humanoid();
  const auto dir =
      simcap::fuzz::write_parts(simcap::fuzz::as_text(data, size), {"clip.asf", "clip.amc"});
  simcap::MotionSource source;
  source.asf = dir / "clip.asf";
  source.amc = dir / "clip.amc";
  simcap::fuzz::expect_value_or_error([&] { simcap::load_motion(source, humanoid, 30.0); });
  return 0;
}
