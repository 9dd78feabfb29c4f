#include "models/bvh_skeleton.h"

#include "models/bvh_names.h"
#include "models/humanoid.h"

namespace simcap {

BvhSkeleton skeleton_from_bvh(const BvhClip& clip) {
  std::vector<std::string> names;
  for (const auto& j : clip.joints) names.push_back(j.name);
  const BvhNaming naming = map_bvh_names(names);
  // H-Anim segment names come from the canonical humanoid, which names them all.
  const Skeleton canonical = build_humanoid();

  BvhSkeleton out;
  out.naming = naming.convention;
  const int n = static_cast<int>(clip.joints.size());
  const auto rest = bvh_joint_positions(clip, -1);
  for (int j = 0; j < n; ++j) {
    const BvhJoint& b = clip.joints[j];
    const bool hanim = !naming.hanim[j].empty();
    std::string name = hanim ? naming.hanim[j] : b.name;
    // An unmapped BVH joint may carry a name the table gave to another joint.
    while (out.skeleton.find(name) >= 0) name += "_bvh";
    std::string segment;
    if (!b.is_end_site) {
      const int c = hanim ? canonical.find(name) : -1;
      segment = c >= 0 ? canonical[c].segment : b.name;
    }
    out.skeleton.add({name, segment, b.parent, rest[j], b.is_end_site});
    out.source_names.push_back(b.name);
    out.is_hanim.push_back(hanim);
    int a = b.parent;
    while (a >= 0 && !out.is_hanim[a]) a = clip.joints[a].parent;
    out.hanim_parent.push_back(a);
  }

  out.motion.fps = clip.fps();
  std::vector<bool> dropped(n, false);
  for (int f = 0; f < clip.frame_count(); ++f) {
    Pose pose = Pose::neutral(out.skeleton);
    for (int j = 0; j < n; ++j) {
      if (clip.joints[j].is_end_site) continue;
      const Eigen::Isometry3d local = bvh_local_transform(clip, j, f);
      pose.rotations[j] = Eigen::Quaterniond(local.linear());
      if (j == 0) {
        pose.root_position = local.translation();
      } else if ((local.translation() - clip.joints[j].offset).norm() > 1e-9) {
        dropped[j] = true;
      }
    }
    out.motion.frames.push_back(std::move(pose));
  }
  for (int j = 0; j < n; ++j) {
    if (dropped[j]) out.dropped_translations.push_back(clip.joints[j].name);
  }
  return out;
}

}  // namespace simcap
