#include "models/joint_names.h"

#include <algorithm>

#include "models/imported_body.h"

namespace simcap {
namespace {

// Finger numbering of H-Anim: 1 thumb, 2 index, 3 middle, 4 ring, 5 little.
std::vector<std::pair<std::string, std::string>> make_mixamo() {
  std::vector<std::pair<std::string, std::string>> t = {
      {"Hips", "humanoid_root"},   {"Spine", "vl1"}, {"Spine1", "vt6"},
      {"Spine2", "vt1"},           {"Neck", "vc7"},  {"Head", "skullbase"},
      {"HeadTop_End", "skull_tip"}};
  for (const auto& [mixamo, hanim] : {std::pair{"Left", "l_"}, std::pair{"Right", "r_"}}) {
    const std::string m(mixamo), h(hanim);
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"Shoulder", "sternoclavicular"},
             {"Arm", "shoulder"},
             {"ForeArm", "elbow"},
             {"Hand", "radiocarpal"},
             {"HandThumb1", "carpometacarpal_1"},
             {"HandThumb2", "metacarpophalangeal_1"},
             {"HandThumb3", "carpal_interphalangeal_1"},
             {"HandMiddle4", "hand_tip"},
             {"UpLeg", "hip"},
             {"Leg", "knee"},
             {"Foot", "talocrural"},
             {"ToeBase", "metatarsophalangeal_2"},
             {"Toe_End", "toe_tip"}}) {
      t.emplace_back(m + from, h + to);
    }
    const char* fingers[] = {"Index", "Middle", "Ring", "Pinky"};
    for (int f = 0; f < 4; ++f) {
      const std::string d = std::to_string(f + 2);
      t.emplace_back(m + "Hand" + fingers[f] + "1", h + "metacarpophalangeal_" + d);
      t.emplace_back(m + "Hand" + fingers[f] + "2", h + "carpal_proximal_interphalangeal_" + d);
      t.emplace_back(m + "Hand" + fingers[f] + "3", h + "carpal_distal_interphalangeal_" + d);
    }
  }
  return t;
}

std::vector<std::pair<std::string, std::string>> make_vrm() {
  std::vector<std::pair<std::string, std::string>> t = {
      {"hips", "humanoid_root"},   {"spine", "vl1"}, {"chest", "vt6"},
      {"upperChest", "vt1"},       {"neck", "vc7"},  {"head", "skullbase"},
      {"jaw", "temporomandibular"}};
  for (const auto& [vrm, hanim] : {std::pair{"left", "l_"}, std::pair{"right", "r_"}}) {
    const std::string v(vrm), h(hanim);
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"Eye", "eyeball_joint"},
             {"Shoulder", "sternoclavicular"},
             {"UpperArm", "shoulder"},
             {"LowerArm", "elbow"},
             {"Hand", "radiocarpal"},
             {"ThumbMetacarpal", "carpometacarpal_1"},
             {"ThumbProximal", "metacarpophalangeal_1"},
             {"ThumbDistal", "carpal_interphalangeal_1"},
             {"UpperLeg", "hip"},
             {"LowerLeg", "knee"},
             {"Foot", "talocrural"},
             {"Toes", "metatarsophalangeal_2"}}) {
      t.emplace_back(v + from, h + to);
    }
    const char* fingers[] = {"Index", "Middle", "Ring", "Little"};
    for (int f = 0; f < 4; ++f) {
      const std::string d = std::to_string(f + 2);
      t.emplace_back(v + fingers[f] + "Proximal", h + "metacarpophalangeal_" + d);
      t.emplace_back(v + fingers[f] + "Intermediate", h + "carpal_proximal_interphalangeal_" + d);
      t.emplace_back(v + fingers[f] + "Distal", h + "carpal_distal_interphalangeal_" + d);
    }
  }
  return t;
}

}  // namespace

const std::vector<std::pair<std::string, std::string>>& joint_name_table(JointNaming naming) {
  static const std::vector<std::pair<std::string, std::string>> none, mixamo = make_mixamo(),
                                                                      vrm = make_vrm();
  return naming == JointNaming::mixamo ? mixamo : naming == JointNaming::vrm ? vrm : none;
}

std::string hanim_joint_name(JointNaming naming, std::string_view name) {
  if (naming == JointNaming::hanim) return std::string(name);
  if (naming == JointNaming::mixamo) {
    const size_t colon = name.rfind(':');
    if (colon != std::string_view::npos) name.remove_prefix(colon + 1);
  }
  for (const auto& [from, to] : joint_name_table(naming)) {
    if (from == name) return to;
  }
  return "";
}

std::string joint_name_in(JointNaming naming, const std::string& hanim) {
  for (const auto& [name, joint] : joint_name_table(naming)) {
    if (joint == hanim) return (naming == JointNaming::mixamo ? "mixamorig:" : "") + name;
  }
  return hanim;
}

JointNaming detect_joint_naming(const std::vector<std::string>& names) {
  JointNaming best = JointNaming::hanim;
  int best_count = -1;
  for (const JointNaming naming : {JointNaming::mixamo, JointNaming::vrm, JointNaming::hanim}) {
    int count = 0;
    for (const std::string& required : required_body_joints()) {
      count += std::any_of(names.begin(), names.end(), [&](const std::string& n) {
        return hanim_joint_name(naming, n) == required;
      });
    }
    if (count > best_count) {
      best = naming;
      best_count = count;
    }
  }
  return best;
}

std::string joint_names_markdown() {
  std::string out =
      "# Joint names of rigged meshes\n\n"
      "Generated by `simcap model joint-names` from models/joint_names.cpp; do not edit by "
      "hand.\n\n"
      "A rigged mesh's bones become H-Anim joints by one of these tables (a scene's "
      "`actors[i].body.joint_map`, `auto` by default: the table that maps the most of the "
      "joints every body needs). `hanim` keeps the names (simcap's own exports). Bones that a "
      "table does not name are folded into their nearest named ancestor: their skin follows "
      "it. Mixamo names match after any `prefix:` (`mixamorig:Hips`). VRM files keep the "
      "humanoid roles in an extension Assimp does not read: their nodes must carry the role "
      "names (`hips`, `leftUpperArm`, ...), as VRM 1.0 spells them.\n";
  for (const JointNaming naming : {JointNaming::mixamo, JointNaming::vrm}) {
    out += "\n## " + std::string(name_of(kJointNamings, naming)) +
           "\n\n| bone | H-Anim joint |\n|---|---|\n";
    for (const auto& [from, to] : joint_name_table(naming)) {
      out += "| " + from + " | " + to + " |\n";
    }
  }
  return out;
}

}  // namespace simcap
