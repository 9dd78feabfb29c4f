// The monocular tracker's capsules (body_shape.h).
#include "tracker/gomez/body_shape.h"

#include <algorithm>

namespace simcap::tracker::gomez {

double standing_height(const Skeleton& skeleton) {
  double low = INFINITY;
  for (const Joint& j : skeleton.joints()) low = std::min(low, j.center.y());
  return skeleton[skeleton.require("skull_tip")].center.y() - low;
}

std::vector<FloorContact> sole_points(const BodyShape& shape, const Skeleton& skeleton) {
  std::vector<FloorContact> out;
  for (const Capsule& c : shape.capsules) {
    if (!skeleton[c.joint].name.ends_with("talocrural")) continue;
    out.push_back({c.joint, c.a - Eigen::Vector3d(0, c.ra, 0)});
    out.push_back({c.joint, c.b - Eigen::Vector3d(0, c.rb, 0)});
  }
  return out;
}

BodyShape make_body_shape(const Skeleton& s, BodyKind kind, const ShapeScales& scales) {
  const double H = standing_height(s);
  const auto c = [&](const char* name) { return s[s.require(name)].center; };
  BodyShape shape;
  // A capsule between two neutral-pose world points, carried by `joint`.
  const auto add = [&](const char* joint, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                       double ra, double rb, Part part) {
    const int j = s.require(joint);
    const std::string name = joint;
    double k = scales.trunk_girth;
    if (part == Part::head) k = scales.head;
    if (part == Part::left_arm || part == Part::right_arm) k = scales.arms;
    if (name.ends_with("hip") || name.ends_with("knee")) k = scales.legs;
    if (name.ends_with("talocrural")) k = 1;
    shape.capsules.push_back({j, a - s[j].center, b - s[j].center, k * ra * H, k * rb * H, part});
  };
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY() * H;
  const double hip_y = 0.5 * (c("l_hip").y() + c("r_hip").y());
  const double shoulder_y = 0.5 * (c("l_shoulder").y() + c("r_shoulder").y());

  if (kind == BodyKind::full) {
    // Pelvis: hip breadth ~0.21 H, depth ~0.12 H.
    add("humanoid_root", {0.045 * H, hip_y + 0.02 * H, -0.005 * H},
        {-0.045 * H, hip_y + 0.02 * H, -0.005 * H}, 0.06, 0.06, Part::torso);
  }
  // Trunk, two upright capsules side by side: breadth ~0.18 H, depth ~0.12 H.
  for (const double side : {1.0, -1.0}) {
    const double w = side * scales.trunk_width * H;
    add("vl5", {0.03 * w, hip_y + 0.07 * H, 0}, {0.035 * w, shoulder_y - 0.05 * H, 0}, 0.06, 0.06,
        Part::torso);
  }
  // Shoulder line over the clavicles, between the shoulder joints.
  add("vt1",
      0.5 * (c("l_shoulder") + c("r_shoulder")) + (c("l_shoulder") - c("r_shoulder")) * 0.45 -
          0.012 * up,
      0.5 * (c("l_shoulder") + c("r_shoulder")) - (c("l_shoulder") - c("r_shoulder")) * 0.45 -
          0.012 * up,
      0.04, 0.04, Part::torso);
  add("vc7", c("vc7"), c("skullbase"), 0.03, 0.03, Part::head);
  const Eigen::Vector3d head_x = c("skullbase");
  add("skullbase", {head_x.x(), head_x.y() + 0.035 * H, head_x.z() + 0.01 * H},
      {head_x.x(), c("skull_tip").y() - 0.052 * H, head_x.z() + 0.006 * H}, 0.05, 0.052,
      Part::head);
  shape.capsules.back().front = Eigen::Vector3d::UnitZ();  // the neutral body faces +Z
  for (const char* side : {"l_", "r_"}) {
    const std::string p = side;
    const Part arm = p == "l_" ? Part::left_arm : Part::right_arm;
    const auto at = [&](const std::string& n) { return c(n.c_str()); };
    add((p + "shoulder").c_str(), at(p + "shoulder"), at(p + "elbow"), 0.03, 0.022, arm);
    add((p + "elbow").c_str(), at(p + "elbow"), at(p + "radiocarpal"), 0.023, 0.015, arm);
    const Eigen::Vector3d tip = at(p + "hand_tip");
    const Eigen::Vector3d wrist = at(p + "radiocarpal");
    add((p + "radiocarpal").c_str(), wrist, wrist + 0.85 * (tip - wrist), 0.017, 0.014, arm);
  }
  if (kind == BodyKind::full) {
    for (const char* side : {"l_", "r_"}) {
      const std::string p = side;
      const Part leg = p == "l_" ? Part::left_leg : Part::right_leg;
      const auto at = [&](const std::string& n) { return c(n.c_str()); };
      add((p + "hip").c_str(), at(p + "hip"), at(p + "knee"), 0.052, 0.037, leg);
      add((p + "knee").c_str(), at(p + "knee"), at(p + "talocrural"), 0.036, 0.027, leg);
      const Eigen::Vector3d ankle = at(p + "talocrural"), toe = at(p + "toe_tip");
      const double sole = toe.y();
      add((p + "talocrural").c_str(), {ankle.x(), sole + 0.02 * H, ankle.z() - 0.035 * H},
          {toe.x(), sole + 0.015 * H, toe.z() - 0.012 * H}, 0.024, 0.018, leg);
    }
  }
  // Pair each capsule with its other-side twin: same joint name after the side prefix, or the
  // two trunk halves.
  auto& caps = shape.capsules;
  for (size_t i = 0; i < caps.size(); ++i) {
    for (size_t k = 0; k < caps.size(); ++k) {
      const std::string& a = s[caps[i].joint].name;
      const std::string& b = s[caps[k].joint].name;
      const bool sides = a.size() > 2 && b.size() > 2 && a.substr(2) == b.substr(2) &&
                         a.substr(0, 2) != b.substr(0, 2) && (a[0] == 'l' || a[0] == 'r');
      const bool halves = i != k && a == b && a == "vl5";
      if (sides || halves) caps[i].mirror = static_cast<int>(k);
    }
  }
  return shape;
}

}  // namespace simcap::tracker::gomez
