// The words a scene file uses for enumerations (occluder and light types, clothing regions,
// body proportions), shared by the reader and the writer so that both spell them alike.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <utility>

#include "scenes/scene.h"

namespace simcap::scene_names {

inline constexpr std::array<std::string_view, 3> kOccluderKinds = {"box", "cylinder", "mesh"};
inline constexpr std::array<std::string_view, 2> kLightKinds = {"directional", "point"};
inline constexpr std::array<std::string_view, kMaterialRegionCount> kRegions = {
    "skin", "shirt", "trousers", "shoes", "hair"};

// The body proportions a scene may set, each a fraction of standing height (or of a breadth).
inline constexpr std::array<std::pair<std::string_view, double BodyProportions::*>, 13>
    kProportions = {{{"shoulder_height", &BodyProportions::shoulder_height},
                     {"chin_height", &BodyProportions::chin_height},
                     {"hip_height", &BodyProportions::hip_height},
                     {"knee_height", &BodyProportions::knee_height},
                     {"ankle_height", &BodyProportions::ankle_height},
                     {"upper_arm", &BodyProportions::upper_arm},
                     {"forearm", &BodyProportions::forearm},
                     {"hand", &BodyProportions::hand},
                     {"foot_length", &BodyProportions::foot_length},
                     {"shoulder_width", &BodyProportions::shoulder_width},
                     {"hip_width", &BodyProportions::hip_width},
                     {"shoulder_joint_spacing", &BodyProportions::shoulder_joint_spacing},
                     {"hip_joint_spacing", &BodyProportions::hip_joint_spacing}}};

inline std::string_view occluder_kind(Occluder::Kind k) {
  return kOccluderKinds[static_cast<int>(k)];
}
inline std::string_view light_kind(Light::Kind k) {
  return kLightKinds[static_cast<int>(k)];
}

// "a, b or c" for error messages.
template <typename Words>
std::string one_of(const Words& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += i + 1 == words.size() ? " or " : ", ";
    out += words[i];
  }
  return out;
}

}  // namespace simcap::scene_names
