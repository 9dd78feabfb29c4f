// Joint rotations from joint positions: the motion of simcap's humanoid whose HE15 bones point
// where a track's joints do, so that a tracker's positions can leave as BVH, X3D or BAP.
#pragma once

#include <string>

#include "core/joint_track.h"
#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

// build_humanoid() at the height whose limb bones (hip-knee, knee-ankle, shoulder-elbow,
// elbow-wrist) fit the track's best: the median over those bones of the ratio of their mean
// tracked length to the unit humanoid's. Throws Error when the track lacks HE15 joints.
Skeleton humanoid_for_track(const JointTrack& track);

struct TrackMotion {
  Motion motion;  // one pose per frame from the track's first to its last frame
  int held = 0;   // frames without every HE15 joint (or absent): the previous pose is held
};

// Per frame, a pose of `skeleton` (from humanoid_for_track) whose bones point along the track's:
// the pelvis turned so that its hips and its spine line (humanoid_root to vc7) point as the
// track's, the chest (vt1) likewise with the shoulders, each clavicle towards its tracked
// shoulder (a shrug lifts the arm); neck (vc7 to skullbase), upper arms,
// forearms, thighs and shanks along the tracked bones, elbows and knees as hinges about the
// axis normal to the plane the track bends them in (a straight limb keeps the shortest turn);
// hands, feet and head continue their limbs. The root sits at the tracked humanoid_root. The
// joints' positions differ from the track's by the differences of bone lengths only (the
// spine between the pelvis and vt1 does not bend, which shifts the shoulders by a few mm).
TrackMotion motion_from_track(const JointTrack& track, const Skeleton& skeleton, double fps);

}  // namespace simcap
