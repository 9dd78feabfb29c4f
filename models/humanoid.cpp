#include "models/humanoid.h"

#include <iterator>
#include <sstream>
#include <utility>

#include "core/error.h"

namespace simcap {

const std::vector<std::string>& he15_joints() {
  static const std::vector<std::string> names = {
      "humanoid_root", "vc7",     "skullbase",     "l_shoulder",    "r_shoulder",
      "l_elbow",       "r_elbow", "l_radiocarpal", "r_radiocarpal", "l_hip",
      "r_hip",         "l_knee",  "r_knee",        "l_talocrural",  "r_talocrural"};
  return names;
}

void check_proportions(const BodyProportions& p) {
  const std::pair<const char*, double> rising[] = {
      {"ankle_height", p.ankle_height}, {"knee_height", p.knee_height},
      {"hip_height", p.hip_height},     {"shoulder_height", p.shoulder_height},
      {"chin_height", p.chin_height},   {"the head top", 1.0}};
  for (size_t i = 1; i < std::size(rising); ++i) {
    if (rising[i - 1].second < rising[i].second) continue;
    std::ostringstream message;
    message << "body proportions: " << rising[i - 1].first << " (" << rising[i - 1].second
            << ") must lie below " << rising[i].first << " (" << rising[i].second
            << "): heights rise from the ankle to the chin, in fractions of the height";
    throw Error(message.str());
  }
}

Skeleton build_humanoid(const BodyParameters& body) {
  const double H = body.height;
  if (!(H >= 0.5 && H <= 2.6)) {
    throw Error("body height must be in [0.5, 2.6] m, got " + std::to_string(H));
  }
  const BodyProportions& p = body.proportions;
  check_proportions(p);
  Skeleton s;
  auto add = [&](const std::string& name, const std::string& segment, const std::string& parent,
                 double x, double y, double z, bool site = false) {
    return s.add(
        {name, segment, parent.empty() ? -1 : s.require(parent), {x * H, y * H, z * H}, site});
  };

  // Pelvis and spine. The spine lies slightly behind the body's mid-plane (negative z); its
  // joints interpolate between the pelvis and C7 at the shoulder line.
  const double root_y = p.hip_height + 0.035;
  add("humanoid_root", "sacrum", "", 0, root_y, 0);
  add("sacroiliac", "pelvis", "humanoid_root", 0, root_y, 0);
  const double c7_y = p.shoulder_height + 0.004;
  const std::pair<const char*, const char*> spine[] = {
      {"vl5", "l5"}, {"vl3", "l3"}, {"vl1", "l1"}, {"vt10", "t10"},
      {"vt6", "t6"}, {"vt1", "t1"}, {"vc7", "c7"}};
  const double spine_t[] = {0.0, 0.14, 0.28, 0.46, 0.68, 0.93, 1.0};
  const double spine_z[] = {-0.005, -0.010, -0.012, -0.016, -0.020, -0.016, -0.014};
  std::string parent = "humanoid_root";
  for (int i = 0; i < 7; ++i) {
    add(spine[i].first, spine[i].second, parent, 0, root_y + spine_t[i] * (c7_y - root_y),
        spine_z[i]);
    parent = spine[i].first;
  }
  const double skullbase_y = 0.5 * (p.chin_height + 1.0) - 0.03;
  add("vc4", "c4", "vc7", 0, 0.5 * (c7_y + skullbase_y), -0.008);
  add("skullbase", "skull", "vc4", 0, skullbase_y, -0.004);
  add("skull_tip", "", "skullbase", 0, 1.0, 0.0, true);

  // Legs. +X is the humanoid's left.
  const double hip_x = 0.5 * p.hip_joint_spacing * p.hip_width;
  const double heel_to_ankle = 0.25 * p.foot_length;
  for (const auto& [side, sign] : {std::pair{"l_", 1.0}, std::pair{"r_", -1.0}}) {
    const std::string s_(side);
    add(s_ + "hip", s_ + "thigh", "sacroiliac", sign * hip_x, p.hip_height, 0);
    add(s_ + "knee", s_ + "calf", s_ + "hip", sign * hip_x, p.knee_height, 0.004);
    add(s_ + "talocrural", s_ + "talus", s_ + "knee", sign * hip_x, p.ankle_height, -0.004);
    add(s_ + "metatarsophalangeal_2", s_ + "tarsal_proximal_phalanx_2", s_ + "talocrural",
        sign * (hip_x + 0.008), 0.010, 0.72 * p.foot_length - heel_to_ankle);
    add(s_ + "toe_tip", "", s_ + "metatarsophalangeal_2", sign * (hip_x + 0.010), 0.006,
        p.foot_length - heel_to_ankle, true);
  }

  // Shoulder girdle and arms, hanging at the sides with the palms facing the thighs.
  const double shoulder_x = 0.5 * p.shoulder_joint_spacing * p.shoulder_width;
  for (const auto& [side, sign] : {std::pair{"l_", 1.0}, std::pair{"r_", -1.0}}) {
    const std::string s_(side);
    add(s_ + "sternoclavicular", s_ + "clavicle", "vt1", sign * 0.012, p.shoulder_height - 0.010,
        0.020);
    const double shoulder_y = p.shoulder_height - 0.012 + p.shoulder_rise;
    add(s_ + "shoulder", s_ + "upperarm", s_ + "sternoclavicular", sign * shoulder_x, shoulder_y,
        -0.006);
    const double elbow_y = shoulder_y - p.upper_arm;
    add(s_ + "elbow", s_ + "forearm", s_ + "shoulder", sign * (shoulder_x + 0.010), elbow_y,
        -0.010);
    const double wrist_y = elbow_y - p.forearm;
    add(s_ + "radiocarpal", s_ + "hand", s_ + "elbow", sign * (shoulder_x + 0.016), wrist_y, 0.004);
    add(s_ + "hand_tip", "", s_ + "radiocarpal", sign * (shoulder_x + 0.018), wrist_y - p.hand,
        0.008, true);
  }
  return s;
}

}  // namespace simcap
