#include "tracker/track_export.h"

#include <algorithm>

#include "core/joint_track.h"
#include "models/body_mesh.h"
#include "models/bvh_export.h"
#include "models/pose_from_joints.h"
#include "models/x3d_export.h"
#include "tracker/gomez/bap_export.h"

namespace simcap::tracker {

int export_track_motion(const std::filesystem::path& track, double fps,
                        const std::vector<MotionExport>& formats) {
  if (formats.empty()) return 0;
  const JointTrack joints = read_joint_track(track / "joints3d.csv");
  const Skeleton skeleton = humanoid_for_track(joints);
  const TrackMotion m = motion_from_track(joints, skeleton, fps);
  auto wants = [&](MotionExport f, const char* file) {
    return std::find(formats.begin(), formats.end(), f) != formats.end() &&
           !std::filesystem::exists(track / file);
  };
  if (wants(MotionExport::bvh, "motion.bvh")) write_bvh(track / "motion.bvh", skeleton, m.motion);
  if (wants(MotionExport::x3d, "motion.x3d")) {
    // The scene colours' defaults (scenes/scene.h), sRGB.
    const std::array<Eigen::Vector3f, kMaterialRegionCount> colors = {
        Eigen::Vector3f(0.85f, 0.66f, 0.53f), Eigen::Vector3f(0.20f, 0.35f, 0.65f),
        Eigen::Vector3f(0.25f, 0.25f, 0.30f), Eigen::Vector3f(0.10f, 0.10f, 0.10f),
        Eigen::Vector3f(0.25f, 0.17f, 0.10f)};
    write_x3d_humanoid(track / "motion.x3d", "track", skeleton, build_body_mesh(skeleton), colors,
                       &m.motion);
  }
  if (wants(MotionExport::bap, "motion.bap")) {
    std::vector<int> numbers(m.motion.frames.size());
    for (size_t k = 0; k < numbers.size(); ++k)
      numbers[k] = joints.frames.front() + static_cast<int>(k);
    write_bap(track / "motion.bap", gomez::bap_from_motion(skeleton, m.motion, numbers, "track"));
  }
  return m.held;
}

}  // namespace simcap::tracker
