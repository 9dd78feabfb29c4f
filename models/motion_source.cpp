#include "models/motion_source.h"

#include "models/bvh.h"
#include "models/resample.h"
#include "models/retarget.h"

namespace simcap {

Motion load_motion(const MotionSource& source, const Skeleton& skeleton, double fps) {
  if (source.bvh.empty()) return generate_procedural(source.procedural, skeleton, fps);
  const BvhClip clip = read_bvh(source.bvh, {.metres_per_unit = source.bvh_metres_per_unit});
  return resample_motion(retarget_bvh(clip, skeleton).motion, fps);
}

}  // namespace simcap
