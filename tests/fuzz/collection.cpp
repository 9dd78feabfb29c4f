// Fuzz target: a collection spec (load_collection) and the resolution of its first sequences
// (collection_sequence). The input's parts are the spec and a scene it may name
// ("==> spec.yaml <==", "==> scene.yaml <=="); clips/ holds one BVH clip, so that
// `folder: clips` names a folder with a clip in it.
#include <algorithm>

#include "collect/collection_spec.h"
#include "core/atomic_file.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

constexpr const char* kClip = R"(HIERARCHY
ROOT Hips
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
  End Site
  {
    OFFSET 0 10 0
  }
}
MOTION
Frames: 2
Frame Time: 0.0333333
0 90 0 0 0 0
0 90 0 0 10 0
)";

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto dir =
      simcap::fuzz::write_parts(simcap::fuzz::as_text(data, size), {"spec.yaml", "scene.yaml"});
  std::filesystem::create_directories(dir / "clips");
  simcap::write_text_atomic(dir / "clips" / "walk.bvh", kClip);
  simcap::fuzz::expect_value_or_error([&] {
    const auto spec = simcap::load_collection(dir / "spec.yaml");
    for (int id = 0; id < std::min(spec.count, 4); ++id) simcap::collection_sequence(spec, id);
  });
  return 0;
}
