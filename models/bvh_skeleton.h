// A simcap Skeleton and Motion taken straight from a BVH clip, with no retargeting: the clip's own
// joints and segment lengths, renamed to H-Anim where the name table maps them.
#pragma once

#include <string>
#include <vector>

#include "models/bvh.h"
#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

// Joint j of `skeleton` is joint j of the clip (same order, end sites become sites), so
//   joint_positions(skeleton, motion.frames[f]) == bvh_joint_positions(clip, f)
// (the clip's TRUE joint positions, in metres; tested to 1e-9 m). Neutral centres are the rest
// offsets; BVH rest frames are world-aligned like simcap's, so Pose::rotations[j] is exactly the
// clip's parent-relative rotation of joint j and root_position is the root's offset plus its
// position channels.
//
// For a benchmark that wants H-Anim joints only (e.g. SIK on the clip's own segment lengths):
// joints the table does not map (CMU's LHipJoint, lowerneck, fingers...) stay in the skeleton
// under their BVH names, so positions remain exact. The orientation of an H-Anim joint j
// relative to its H-Anim parent is G[hanim_parent[j]]^-1 * G[j] with G = forward_kinematics();
// it equals motion.frames[f].rotations[j] whenever the joints in between never rotate.
struct BvhSkeleton {
  Skeleton skeleton;
  Motion motion;                          // one pose per clip frame, fps = clip fps
  std::vector<std::string> source_names;  // per joint: the name in the BVH file
  std::vector<bool> is_hanim;             // per joint: renamed by the name table
  // Per joint: the nearest proper ancestor whose name is H-Anim (-1 when none).
  std::vector<int> hanim_parent;
  std::string naming;  // the name table that matched (see bvh_names.h)
  // Non-root joints with position channels whose values move them away from their rest offset
  // (a simcap Skeleton has fixed segment lengths, so that motion is not represented).
  std::vector<std::string> dropped_translations;
};

BvhSkeleton skeleton_from_bvh(const BvhClip& clip);

}  // namespace simcap
