#include "models/bvh_names.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace simcap {
namespace {

// One row of a naming table. `hanim` empty marks a known intermediate joint. In both strings
// "{Side}" stands for Left/Right, "{S}" for L/R and "{s}" for l/r (H-Anim's side prefix), so
// each sided row is written once.
struct Row {
  const char* bvh;
  const char* hanim;
};

struct Table {
  const char* name;
  std::vector<Row> rows;
};

// Which joint a BVH name means follows from what its rotation moves: a BVH joint's rotation
// turns the bone from it to its children, as an H-Anim joint turns its segment.
const std::vector<Table>& tables() {
  static const std::vector<Table> t = {
      // CMU's BVH conversion of its ASF skeletons (the clips in models/assets): ASF bone
      // names for the spine and hands, Biovision-like names elsewhere. LeftWrist turns the
      // hand; lhand (always zero) only carries the fingers.
      {"cmu-asf",
       {{"Hips", "humanoid_root"},
        {"{S}HipJoint", ""},
        {"{Side}Hip", "{s}_hip"},
        {"{Side}Knee", "{s}_knee"},
        {"{Side}Ankle", "{s}_talocrural"},
        {"{Side}Toe", "{s}_metatarsophalangeal_2"},
        {"{Side}Toe_End", "{s}_toe_tip"},
        {"lowerback", "vl5"},
        {"Chest", "vl1"},
        {"Chest2", "vt6"},
        {"lowerneck", "vc7"},
        {"Neck", "vc4"},
        {"Head", "skullbase"},
        {"Head_End", "skull_tip"},
        {"{Side}Collar", "{s}_sternoclavicular"},
        {"{Side}Shoulder", "{s}_shoulder"},
        {"{Side}Elbow", "{s}_elbow"},
        {"{Side}Wrist", "{s}_radiocarpal"},
        {"{s}hand", ""},
        {"{S}Fingers_End", "{s}_hand_tip"}}},
      // Acclaim ASF/AMC bone names of the CMU database (models/asf_amc.h: a bone's joint sits
      // at its proximal end). lwrist only twists the forearm; lhand bends the wrist.
      {"acclaim",
       {{"root", "humanoid_root"},
        {"{s}hipjoint", ""},
        {"{s}femur", "{s}_hip"},
        {"{s}tibia", "{s}_knee"},
        {"{s}foot", "{s}_talocrural"},
        {"{s}toes", "{s}_metatarsophalangeal_2"},
        {"{s}toes_End", "{s}_toe_tip"},
        {"lowerback", "vl5"},
        {"upperback", "vl1"},
        {"thorax", "vt6"},
        {"lowerneck", "vc7"},
        {"upperneck", "vc4"},
        {"head", "skullbase"},
        {"head_End", "skull_tip"},
        {"{s}clavicle", "{s}_sternoclavicular"},
        {"{s}humerus", "{s}_shoulder"},
        {"{s}radius", "{s}_elbow"},
        {"{s}wrist", ""},
        {"{s}hand", "{s}_radiocarpal"},
        {"{s}hand_End", "{s}_hand_tip"},
        {"{s}fingers_End", "{s}_hand_tip"}}},
      // CMU's "3dsMax-friendly" / MotionBuilder-friendly release: LeftShoulder is the clavicle,
      // LeftArm the shoulder joint.
      {"cmu-3dsmax",
       {{"Hips", "humanoid_root"},
        {"{S}HipJoint", ""},
        {"{Side}UpLeg", "{s}_hip"},
        {"{Side}Leg", "{s}_knee"},
        {"{Side}Foot", "{s}_talocrural"},
        {"{Side}ToeBase", "{s}_metatarsophalangeal_2"},
        {"{Side}ToeBase_End", "{s}_toe_tip"},
        {"LowerBack", "vl5"},
        {"Spine", "vl1"},
        {"Spine1", "vt6"},
        {"Neck", "vc7"},
        {"Neck1", "vc4"},
        {"Head", "skullbase"},
        {"Head_End", "skull_tip"},
        {"{Side}Shoulder", "{s}_sternoclavicular"},
        {"{Side}Arm", "{s}_shoulder"},
        {"{Side}ForeArm", "{s}_elbow"},
        {"{Side}Hand", "{s}_radiocarpal"},
        {"{Side}FingerBase", ""},
        {"{Side}HandIndex1", ""},
        {"{Side}HandIndex1_End", "{s}_hand_tip"}}},
      // Mixamo and Autodesk HumanIK (namespace prefixes such as "mixamorig:" are ignored).
      {"mixamo",
       {{"Hips", "humanoid_root"},
        {"Spine", "vl3"},
        {"Spine1", "vt10"},
        {"Spine2", "vt6"},
        {"Neck", "vc7"},
        {"Neck1", "vc4"},
        {"Head", "skullbase"},
        {"HeadTop_End", "skull_tip"},
        {"{Side}Shoulder", "{s}_sternoclavicular"},
        {"{Side}Arm", "{s}_shoulder"},
        {"{Side}ForeArm", "{s}_elbow"},
        {"{Side}Hand", "{s}_radiocarpal"},
        {"{Side}UpLeg", "{s}_hip"},
        {"{Side}Leg", "{s}_knee"},
        {"{Side}Foot", "{s}_talocrural"},
        {"{Side}ToeBase", "{s}_metatarsophalangeal_2"},
        {"{Side}Toe_End", "{s}_toe_tip"}}},
      // Poser / Daz (also CMU's "Daz-friendly" release, whose lButtock sits like LHipJoint).
      {"daz",
       {{"hip", "humanoid_root"},
        {"abdomen", "vl5"},
        {"chest", "vt6"},
        {"neck", "vc7"},
        {"head", "skullbase"},
        {"head_End", "skull_tip"},
        {"{s}Buttock", ""},
        {"{s}Thigh", "{s}_hip"},
        {"{s}Shin", "{s}_knee"},
        {"{s}Foot", "{s}_talocrural"},
        {"{s}Toe", "{s}_metatarsophalangeal_2"},
        {"{s}Collar", "{s}_sternoclavicular"},
        {"{s}Shldr", "{s}_shoulder"},
        {"{s}ForeArm", "{s}_elbow"},
        {"{s}Hand", "{s}_radiocarpal"}}},
      // The original Biovision naming.
      {"biovision",
       {{"Hips", "humanoid_root"},
        {"Chest", "vl5"},
        {"Neck", "vc7"},
        {"Head", "skullbase"},
        {"Head_End", "skull_tip"},
        {"{Side}Collar", "{s}_sternoclavicular"},
        {"{Side}UpArm", "{s}_shoulder"},
        {"{Side}LowArm", "{s}_elbow"},
        {"{Side}Hand", "{s}_radiocarpal"},
        {"{Side}UpLeg", "{s}_hip"},
        {"{Side}LowLeg", "{s}_knee"},
        {"{Side}Foot", "{s}_talocrural"}}},
      // H-Anim names (simcap's own exports): themselves; end sites by their parent.
      {"h-anim",
       {{"humanoid_root", "humanoid_root"},
        {"sacroiliac", "sacroiliac"},
        {"{s}_hip", "{s}_hip"},
        {"{s}_knee", "{s}_knee"},
        {"{s}_talocrural", "{s}_talocrural"},
        {"{s}_metatarsophalangeal_2", "{s}_metatarsophalangeal_2"},
        {"{s}_toe_tip", "{s}_toe_tip"},
        {"{s}_metatarsophalangeal_2_End", "{s}_toe_tip"},
        {"vl5", "vl5"},
        {"vl3", "vl3"},
        {"vl1", "vl1"},
        {"vt10", "vt10"},
        {"vt6", "vt6"},
        {"vt1", "vt1"},
        {"vc7", "vc7"},
        {"vc4", "vc4"},
        {"skullbase", "skullbase"},
        {"skull_tip", "skull_tip"},
        {"skullbase_End", "skull_tip"},
        {"{s}_sternoclavicular", "{s}_sternoclavicular"},
        {"{s}_shoulder", "{s}_shoulder"},
        {"{s}_elbow", "{s}_elbow"},
        {"{s}_radiocarpal", "{s}_radiocarpal"},
        {"{s}_hand_tip", "{s}_hand_tip"},
        {"{s}_radiocarpal_End", "{s}_hand_tip"}}},
  };
  return t;
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// "mixamorig:LeftArm" -> "leftarm".
std::string normalise(std::string_view name) {
  const size_t colon = name.rfind(':');
  if (colon != std::string_view::npos) name.remove_prefix(colon + 1);
  return lower(name);
}

std::string substitute(std::string text, bool left) {
  const std::pair<const char*, const char*> keys[] = {
      {"{Side}", left ? "Left" : "Right"}, {"{S}", left ? "L" : "R"}, {"{s}", left ? "l" : "r"}};
  for (const auto& [key, value] : keys) {
    for (size_t at = text.find(key); at != std::string::npos; at = text.find(key)) {
      text.replace(at, std::string_view(key).size(), value);
    }
  }
  return text;
}

// Normalised BVH name -> H-Anim name ("" for intermediates), both sides expanded.
std::map<std::string, std::string> expand(const Table& table) {
  std::map<std::string, std::string> out;
  for (const Row& row : table.rows) {
    for (bool left : {true, false}) {
      out.emplace(normalise(substitute(row.bvh, left)), substitute(row.hanim, left));
    }
  }
  return out;
}

}  // namespace

std::vector<std::string> bvh_naming_conventions() {
  std::vector<std::string> names;
  for (const Table& t : tables()) names.emplace_back(t.name);
  return names;
}

BvhNaming map_bvh_names(const std::vector<std::string>& names) {
  std::vector<std::string> normalised;
  for (const auto& n : names) normalised.push_back(normalise(n));
  const Table* best = nullptr;
  std::map<std::string, std::string> best_map;
  size_t best_score = 0;
  for (const Table& table : tables()) {
    auto map = expand(table);
    const size_t score = std::count_if(normalised.begin(), normalised.end(),
                                       [&](const std::string& n) { return map.count(n) > 0; });
    if (!best || score > best_score) {
      best = &table;
      best_map = std::move(map);
      best_score = score;
    }
  }
  BvhNaming naming;
  naming.convention = best->name;
  naming.hanim.resize(names.size());
  naming.intermediate.resize(names.size(), false);
  std::set<std::string> used;  // a clip naming two joints alike keeps the first
  for (size_t i = 0; i < names.size(); ++i) {
    const auto it = best_map.find(normalised[i]);
    if (it == best_map.end()) continue;
    if (it->second.empty()) {
      naming.intermediate[i] = true;
    } else if (used.insert(it->second).second) {
      naming.hanim[i] = it->second;
    }
  }
  return naming;
}

}  // namespace simcap
