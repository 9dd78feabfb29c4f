// Retargeting of a BVH clip onto a simcap skeleton (build_humanoid): joint rotations mapped by
// H-Anim name with rest-pose alignment, the target's own segment lengths, the root trajectory
// scaled by leg length and the feet put on the floor.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "models/bvh.h"
#include "models/foot_contact.h"
#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

struct RetargetOptions {
  // Put the feet on the floor (y = 0): first raise or lower the whole motion so that the median
  // over frames of the lowest sole point (humanoid_feet) is on the floor, the right thing for
  // clips where a foot is down in most frames; then, per frame, move the root vertically so that
  // the lowest sole point touches the floor whenever it is within `ground_band` of it, fading
  // the correction out between one and two bands (feet higher up are jumping). The proportions
  // of the target's legs and feet differ from the actor's, so copied rotations alone leave feet
  // a few centimetres in or above the floor.
  bool place_on_floor = true;
  double ground_band = 0.03;  // metres; 0: only the whole-motion offset
  // For the foot figures in the report (see FootStats).
  double contact_height = 0.02;  // metres
  double min_contact_s = 0.1;
};

struct RetargetReport {
  std::string naming;                                       // the BVH name table that matched
  std::vector<std::pair<std::string, std::string>> mapped;  // BVH joint -> target joint
  // BVH joints without a target joint whose rotation still reaches the target through mapped
  // descendants (e.g. CMU's LHipJoint between Hips and LeftHip, lowerneck).
  std::vector<std::string> folded;
  // BVH joints (and end sites) whose motion is lost: no target joint and no mapped descendant.
  std::vector<std::string> unmapped;
  // Target joints with no BVH joint: they keep their neutral rotation relative to their parent.
  std::vector<std::string> target_unmapped;
  double root_scale = 1.0;    // target leg length / source leg length
  double floor_offset = 0.0;  // metres added to the root height of every frame by place_on_floor
  double ground_max = 0.0;    // metres: the largest per-frame correction on top of floor_offset
  FootStats source_feet;      // the clip's foot joints and end sites (no sole), metres
  FootStats target_feet;      // humanoid_feet() of the result
  // Several lines for people: naming, unmapped joints, foot figures.
  std::string summary() const;
};

struct Retargeted {
  Motion motion;  // at the clip's frame rate, for `target`
  RetargetReport report;
};

// The clip's motion on `target` (a skeleton with H-Anim names such as build_humanoid()).
// Each mapped target joint j takes the world rotation of its BVH joint s composed with a
// rest alignment A_j, the rotation that turns j's neutral bone direction (towards its child)
// into s's rest bone direction, so a T-pose clip drives a skeleton whose arms hang down.
// Throws Error when the clip lacks a joint for humanoid_root or for both hips.
Retargeted retarget_bvh(const BvhClip& clip, const Skeleton& target,
                        const RetargetOptions& options = {});

}  // namespace simcap
