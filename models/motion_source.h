// Where an actor's motion comes from: a motion-capture file (retargeted to the humanoid) or a
// procedural generator. One entry point turns either into a Motion at the renderer's frame rate.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "models/bvh.h"
#include "models/gesture_motion.h"
#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

// Parameters of the action kinds, in the units of their scene keys (scenes/README.md).
struct JumpsSpec {
  int count = 2;            // forward jumps with both feet together
  double distance_m = 0.4;  // length of each jump
  double height_m = 0.15;   // rise of the pelvis in flight over its take-off height
};
struct TurnaroundSpec {
  double distance_m = 1.2;  // walked before the 180 degree turn (at ProceduralSpec::speed_m_s)
};
struct SquatSpec {
  int count = 3;
  double depth = 0.3;  // lowest pelvis descent, a fraction of the standing hip height
};
struct ArmsCrossSpec {
  int count = 3;  // times the arms cross in front of the chest
};
struct SideStepsSpec {
  int count = 2;            // grapevine cycles of four steps, the trailing leg crossing
  double distance_m = 1.2;  // sideways travel, positive to the actor's left
};
struct BendForwardSpec {
  int count = 2;  // times the hands go down to the floor
};
struct KickSpec {
  int count = 2;        // front kicks, right leg first, then alternating
  double height = 0.8;  // kicking ankle's highest point, a fraction of the standing hip height
};
struct ArmSwingsSpec {
  double frequency_hz = 1.5;  // full swings (forward and back) per second
  double amplitude_deg = 60;  // shoulder flexion at the front of a swing
};

// Deterministic procedural motions for the built-in default, tests and the motion suite.
struct ProceduralSpec {
  // One of: "stand" (neutral stance with slight sway), "tpose", "walk_in_place", "walk_path"
  // (walk along a circle of `path_radius`), "arm_raise" (both arms up and down), "turn" (a turn
  // on the spot), an action: "jumps", "turnaround", "squat", "arms_cross", "side_steps",
  // "bend_forward", "kick", "arm_swings" (models/procedural_actions.h), "gestures" (the gesture
  // corpus of models/gesture_motion.h; `duration_s` is then the corpus' own length), or
  // "arm_gesture" (a standing person's communicative gesture, `gesture`).
  std::string kind = "walk_path";
  double duration_s = 4.0;
  double speed_m_s = 1.2;    // walking speed (walk_path) or step rate scale (walk_in_place)
  double path_radius = 1.0;  // metres (walk_path)
  // Total turn in degrees, counter-clockwise seen from above (turn).
  double turn_degrees = 360.0;
  // The action kinds' parameters (models/procedural_actions.h); each action starts and ends
  // standing still and its repetitions fill the duration.
  JumpsSpec jumps{};
  TurnaroundSpec turnaround{};
  SquatSpec squat{};
  ArmsCrossSpec arms_cross{};
  SideStepsSpec side_steps{};
  BendForwardSpec bend_forward{};
  KickSpec kick{};
  ArmSwingsSpec arm_swings{};
  GestureSpec gestures{};  // gestures
  // arm_gesture: one of gesture_names(), after the four synthetic sequences of Gomez Jauregui
  // 2011 §3.6.2 (GRETA gestures): "raise" (both arms up sideways and down: in the image plane),
  // "joy" (hands up before the face, fast), "exclaim" (open arms turning, upper arms crossing
  // the trunk), "ask" (hands pushed towards the front and drawn back: along the depth). The
  // gesture fills the duration once, from and back to arms hanging.
  std::string gesture = "raise";
};

// The gestures of ProceduralSpec::gesture.
const std::vector<std::string>& gesture_names();

struct MotionSource {
  std::filesystem::path bvh;  // when not empty: a BVH file
  // When not empty (and bvh is): an Acclaim AMC motion of the ASF skeleton `asf` (CMU's own
  // format, models/asf_amc.h) at `amc_fps`.
  std::filesystem::path amc, asf;
  double amc_fps = 120.0;
  // BVH: 0 detects the unit from the skeleton's size (CMU: 0.0254 / 0.45); AMC: 0 takes the
  // ASF's :units length.
  double bvh_metres_per_unit = 0.0;
  ProceduralSpec procedural;  // when neither file is given
};

// The clip of a BVH or ASF/AMC source (retargeting's input); Error for a procedural one.
BvhClip read_motion_clip(const MotionSource& source);

// The motion of `source` for `skeleton`, sampled at `fps` (BVH and AMC clips are retargeted and
// resampled with slerp). Throws Error naming the file and line for bad motion files.
Motion load_motion(const MotionSource& source, const Skeleton& skeleton, double fps);

// The procedural motion `spec` for `skeleton` (H-Anim names, as from build_humanoid) at `fps`.
// Walking gaits plant each foot flat (heel rising before toe-off) where it lands, so stance feet
// neither slide nor leave the floor; legs follow by analytic two-bone IK, arms swing against the
// legs. Throws Error for an unknown kind or a skeleton without the H-Anim leg and arm joints.
Motion generate_procedural(const ProceduralSpec& spec, const Skeleton& skeleton, double fps);

// The kinds generate_procedural knows, in the order of ProceduralSpec's comment.
const std::vector<std::string>& procedural_kinds();

}  // namespace simcap
