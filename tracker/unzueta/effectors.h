// The six body parts Unzueta's system follows in the images (thesis ch. 3): head, hands and feet
// by CFOF, the pelvis from the silhouette; and the skeleton joint each stands for in SIK.
#pragma once

#include <array>
#include <string_view>

namespace simcap::tracker {

enum class Effector { head, left_hand, right_hand, left_foot, right_foot, pelvis };
inline constexpr int kEffectorCount = 6;
inline constexpr std::array<Effector, kEffectorCount> kEffectors = {
    Effector::head,      Effector::left_hand,  Effector::right_hand,
    Effector::left_foot, Effector::right_foot, Effector::pelvis};

// "head", "l_hand", "r_hand", "l_foot", "r_foot", "pelvis".
std::string_view effector_name(Effector e);
// The H-Anim joint SIK places from the part: skullbase, l/r_radiocarpal, l/r_talocrural,
// humanoid_root.
std::string_view effector_joint(Effector e);
inline int index_of(Effector e) {
  return static_cast<int>(e);
}

}  // namespace simcap::tracker
