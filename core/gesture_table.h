// A dataset's gt/gestures.csv: the labelled stretches of each actor's motion (a limb's dynamic
// gesture or held static pose, frames inclusive), written by the renderer, read by the scorers.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace simcap {

inline const std::vector<std::string> kGesturesColumns = {"actor", "limb",        "kind",
                                                          "label", "first_frame", "last_frame"};

struct GestureInterval {
  std::string actor, limb;  // limb: "l_hand" or "r_hand"
  std::string kind;         // "dynamic" or "static"
  std::string label;
  int first_frame = 0, last_frame = 0;
};

// Errors name file:line and column (an unknown kind, last_frame before first_frame, ...).
std::vector<GestureInterval> read_gesture_table(const std::filesystem::path& path);

}  // namespace simcap
