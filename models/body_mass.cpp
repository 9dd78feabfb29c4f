#include "models/body_mass.h"

#include <string>

namespace simcap {

BodyMass::BodyMass(const Skeleton& s) {
  const auto add = [&](const std::string& proximal, const std::string& distal, double mass,
                       double com, double distal_scale = 1.0) {
    segments_.push_back(
        {s.require(proximal), distal.empty() ? -1 : s.require(distal), distal_scale, mass, com});
  };
  hips_[0] = s.require("l_hip");
  hips_[1] = s.require("r_hip");
  for (const std::string side : {"l_", "r_"}) {
    add(side + "shoulder", side + "elbow", 0.028, 0.436);              // upper arm
    add(side + "elbow", side + "radiocarpal", 0.016, 0.430);           // forearm
    add(side + "radiocarpal", side + "hand_tip", 0.006, 0.506, 0.45);  // hand, to the knuckles
    add(side + "hip", side + "knee", 0.100, 0.433);                    // thigh
    add(side + "knee", side + "talocrural", 0.0465, 0.433);            // leg
    add(side + "talocrural", side + "metatarsophalangeal_2", 0.0145, 0.50);  // foot
  }
  add("vc7", "skullbase", 0.081, 1.0);  // head and neck: C7-T1 to the ear canal
  add("vc7", "vl1", 0.216, 0.82);       // thorax: C7-T1 to T12-L1
  add("vl1", "vl5", 0.139, 0.44);       // abdomen: T12-L1 to L4-L5
  add("vl5", "", 0.142, 0.105);         // pelvis: L4-L5 to the greater trochanters
}

Eigen::Vector3d BodyMass::center(const std::vector<Eigen::Vector3d>& joints) const {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double mass = 0;
  for (const Segment& g : segments_) {
    const Eigen::Vector3d& p = joints[g.proximal];
    const Eigen::Vector3d d = g.distal < 0
                                  ? 0.5 * (joints[hips_[0]] + joints[hips_[1]])
                                  : Eigen::Vector3d(p + g.distal_scale * (joints[g.distal] - p));
    sum += g.mass * (p + g.com * (d - p));
    mass += g.mass;
  }
  return sum / mass;
}

}  // namespace simcap
