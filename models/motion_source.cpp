#include "models/motion_source.h"

#include <cctype>
#include <string>

#include "core/error.h"
#include "models/asf_amc.h"
#include "models/bvh.h"
#include "models/resample.h"
#include "models/retarget.h"

namespace simcap {

BvhClip read_motion_clip(const MotionSource& source) {
  // An AMC file holds no skeleton; read as BVH it would fail on its first line for another reason.
  std::string extension = source.bvh.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".amc") {
    throw Error(source.bvh.string() +
                ": an Acclaim AMC motion needs its skeleton: give the ASF file with --asf "
                "(or asf: beside amc: in a scene's motion)");
  }
  if (!source.bvh.empty()) {
    return read_bvh(source.bvh, {.metres_per_unit = source.bvh_metres_per_unit});
  }
  if (!source.amc.empty()) {
    return read_asf_amc(source.asf, source.amc,
                        {.fps = source.amc_fps, .metres_per_unit = source.bvh_metres_per_unit});
  }
  throw Error("a procedural motion has no clip");
}

Motion load_motion(const MotionSource& source, const Skeleton& skeleton, double fps) {
  if (source.bvh.empty() && source.amc.empty()) {
    return generate_procedural(source.procedural, skeleton, fps);
  }
  const Motion retargeted = retarget_bvh(read_motion_clip(source), skeleton).motion;
  try {
    return resample_motion(retargeted, fps);
  } catch (const Error& e) {
    throw Error((source.bvh.empty() ? source.amc : source.bvh).string() + ": " + e.what());
  }
}

}  // namespace simcap
