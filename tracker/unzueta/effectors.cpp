#include "tracker/unzueta/effectors.h"

namespace simcap::tracker {

std::string_view effector_name(Effector e) {
  static constexpr std::array<std::string_view, kEffectorCount> names = {
      "head", "l_hand", "r_hand", "l_foot", "r_foot", "pelvis"};
  return names[index_of(e)];
}

std::string_view effector_joint(Effector e) {
  static constexpr std::array<std::string_view, kEffectorCount> joints = {
      "skullbase",    "l_radiocarpal", "r_radiocarpal",
      "l_talocrural", "r_talocrural",  "humanoid_root"};
  return joints[index_of(e)];
}

}  // namespace simcap::tracker
