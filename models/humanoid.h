// The canonical simcap humanoid skeleton: H-Anim 2.0 joint and segment names and hierarchy,
// with joint centres built from body height and segment-length ratios (Drillis & Contini).
#pragma once

#include <string>
#include <vector>

#include "models/skeleton.h"

namespace simcap {

// Segment lengths as fractions of standing height H, from Drillis & Contini (1966) as tabulated
// in D. A. Winter, "Biomechanics and Motor Control of Human Movement", 4th ed. (2009), Fig. 4.1.
// Lateral spacings of the joint centres are simcap's choices and say so.
struct BodyProportions {
  double shoulder_height = 0.818;  // acromion height (Winter Fig. 4.1)
  double chin_height = 0.870;      // (Winter Fig. 4.1)
  double hip_height = 0.530;       // greater trochanter height (Winter Fig. 4.1)
  double knee_height = 0.285;      // (Winter Fig. 4.1)
  double ankle_height = 0.039;     // (Winter Fig. 4.1)
  double upper_arm = 0.186;        // shoulder -> elbow (Winter Fig. 4.1)
  double forearm = 0.146;          // elbow -> wrist (Winter Fig. 4.1)
  double hand = 0.108;             // wrist -> fingertip (Winter Fig. 4.1)
  double foot_length = 0.152;      // heel -> toe tip (Winter Fig. 4.1)
  double shoulder_width = 0.259;   // biacromial breadth (Winter Fig. 4.1)
  double hip_width = 0.191;        // bitrochanteric breadth (Winter Fig. 4.1)
  // simcap choices: joint centres lie inside the bony breadths.
  double shoulder_joint_spacing = 0.80;  // shoulder centres apart, fraction of shoulder_width
  double hip_joint_spacing = 0.50;       // hip centres apart, fraction of hip_width
  // simcap choice: the shoulder joints (and the arms under them) raised above the acromion line
  // by this fraction of height, the clavicles turning up about the sternoclavicular joints, as a
  // shrug or a mocap skeleton's convention does (CMU 131_01's subject: about 0.04). Negative
  // lowers them. The trunk and neck keep their shape. A retargeted clip turns the clavicles to
  // its own directions (retarget.h), which undoes most of it.
  double shoulder_rise = 0.0;
};

struct BodyParameters {
  double height = 1.75;  // metres, standing, head top to floor
  BodyProportions proportions;
};

// Throws Error unless the heights rise from the feet to the head: ankle_height < knee_height <
// hip_height < shoulder_height < chin_height < 1 (the message names the two out of order).
void check_proportions(const BodyProportions& proportions);

// Builds the skeleton in the neutral pose (standing upright, facing +Z, arms hanging at the
// sides, feet on the floor y = 0, pelvis above the origin). Joints, parents first:
//   humanoid_root, sacroiliac, l/r_hip, l/r_knee, l/r_talocrural, l/r_metatarsophalangeal_2,
//   vl5, vl3, vl1, vt10, vt6, vt1, vc7, vc4, skullbase, l/r_sternoclavicular, l/r_shoulder,
//   l/r_elbow, l/r_radiocarpal; sites skull_tip, l/r_hand_tip, l/r_toe_tip.
Skeleton build_humanoid(const BodyParameters& body = {});

// The evaluation joint set "HE15" (HumanEva layout, H-Anim names): humanoid_root, vc7,
// skullbase, then left/right shoulder, elbow, radiocarpal, hip, knee, talocrural.
const std::vector<std::string>& he15_joints();

}  // namespace simcap
