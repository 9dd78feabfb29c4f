// The gesture corpus (Unzueta 2009 §5.6): a standing subject drawing the digits 0-9 in the air
// with the right hand, waving, pointing and raising either arm, between slow transitions and
// held poses, with every gesture's interval and label. A seed varies order, speed and size.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "models/motion.h"
#include "models/skeleton.h"

namespace simcap {

struct GestureSpec {
  // Each of the kinds below is performed this many times, in an order drawn from the seed.
  int repetitions = 2;
  // Any of "0".."9" (right hand), "wave", "point", "raise" (each with either hand). Empty: all.
  std::vector<std::string> gestures;
  std::uint64_t seed = 1;
  // Mean hand speed while gesturing, m/s: each subject (seed) draws a base in this range and
  // each performance varies it by +-15%.
  double min_speed = 1.0, max_speed = 1.6;
  // Height of a drawn digit, m: a subject draws a base, each performance varies it by +-10%.
  double min_size = 0.30, max_size = 0.45;
  // Peak hand speed of the movements between gestures, m/s (slow, so they are not gestures).
  double transition_speed = 0.4;
};

// The gestures generate_gestures knows: "0".."9", "wave", "point", "raise".
const std::vector<std::string>& gesture_kinds();

// The corpus for `skeleton` (H-Anim, from build_humanoid) at `fps`: the calibration posture
// (hands beside the head, feet apart; tracker/unzueta/initial_regions.h) for its first second,
// then the gestures, each with a "dynamic" label over its fast part and "static" labels over the
// held poses ("down" at rest, "forward" after pointing, "up" after raising). Throws Error for
// an unknown gesture, a bad range or a skeleton without the H-Anim arm and leg joints.
Motion generate_gestures(const GestureSpec& spec, const Skeleton& skeleton, double fps);

}  // namespace simcap
