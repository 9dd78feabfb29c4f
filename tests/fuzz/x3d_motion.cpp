// Fuzz target: an X3D HAnimMotion (parse_x3d_motion) for the default humanoid, resampled to 30
// frames/s as a motion is before rendering (its frameDuration sets the work), up to ten minutes.
#include "models/humanoid.h"
#include "models/resample.h"
#include "models/x3d_humanoid.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const simcap::Skeleton humanoid = simcap::build_humanoid();
  simcap::fuzz::expect_value_or_error([&] {
    const simcap::Motion motion =
        simcap::parse_x3d_motion(simcap::fuzz::as_text(data, size), "fuzz.x3d", humanoid);
    // Resampling is linear in the frames it makes and the limits let it make up to
    // kMaxPoseSamples rotations: 42 minutes of motion (three frames 840 s apart) took 12 s
    // under ASan on a busy machine, which libFuzzer reports as a hang. Ten minutes at 30
    // frames/s keeps a real hang detectable.
    if (motion.duration_s() <= 600) simcap::resample_motion(motion, 30.0);
  });
  return 0;
}
