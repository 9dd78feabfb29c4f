#include "tracker/moschini/body_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace simcap::tracker {
namespace {

// Capsule 0 is the head; then left/right pairs in this order of parts.
constexpr std::array<std::string_view, kCapsuleCount> kNames = {
    "head",       "pelvis_left", "pelvis_right", "chest_left", "chest_right", "l_upperarm",
    "r_upperarm", "l_forearm",   "r_forearm",    "l_hand",     "r_hand",      "l_thigh",
    "r_thigh",    "l_calf",      "r_calf",       "l_shoe",     "r_shoe"};

Eigen::Vector3d mirrored(const Eigen::Vector3d& v) {
  return {-v.x(), v.y(), v.z()};
}

}  // namespace

std::string_view capsule_name(int capsule) {
  return kNames.at(capsule);
}

int mirrored_capsule(int capsule) {
  if (capsule == 0) return 0;
  return capsule % 2 ? capsule + 1 : capsule - 1;
}

double stature(const BodyDimensions& d) {
  return (d.calf + d.thigh + 2 * d.torso_half + d.head) / (1 - 0.039);
}

BodySurface typical_surface(const BodyDimensions& d) {
  const double H = stature(d);
  // Girth c as a fraction of stature -> radius in metres.
  auto girth = [H](double c) { return c * H / (2 * std::numbers::pi); };
  BodySurface s;
  auto pair = [&](int left, int segment_left, int segment_right, const Eigen::Vector3d& a,
                  const Eigen::Vector3d& b, double ra, double rb) {
    s[left] = {segment_left, a, b, ra, rb};
    s[left + 1] = {segment_right, mirrored(a), mirrored(b), ra, rb};
  };
  // Trunk: two capsules as deep as the trunk, their centres apart so that together they are as
  // broad. Pelvis from the hip line (its lower caps reach the crotch) to the spine joint; chest
  // from there to the shoulders' level, in front of the line from the hips to C7, which the
  // thoracic curve carries to the back (by 0.5% of stature at the waist, 1.6% at the chest).
  const double pelvis_r = 0.06 * H, chest_r = 0.0675 * H;
  const double pelvis_length = d.torso_half + d.spine_pivot;
  const double chest_length = d.torso_half - d.spine_pivot;
  pair(1, kPelvis, kPelvis, {(0.1025 - 0.06) * H, 0, 0}, {(0.1025 - 0.06) * H, pelvis_length, 0},
       pelvis_r, pelvis_r);
  pair(3, kChest, kChest, {(0.0875 - 0.0675) * H, 0, 0.005 * H},
       {(0.0875 - 0.0675) * H, std::max(0.0, chest_length - chest_r), 0.016 * H}, chest_r, chest_r);
  // Head: the neck from vc7 widening into the skull, its top at the head stick's end, both in
  // front of the cervical spine (head breadth 0.088, length 0.112 of stature).
  const double skull_r = 0.05 * H;
  s[0] = {kHead,
          {0, 0, 0.005 * H},
          {0, std::max(0.0, d.head - skull_r), 0.012 * H},
          girth(0.22),
          skull_r};
  pair(5, kLUpperArm, kRUpperArm, {0, 0, 0}, {0, -d.upper_arm, 0}, girth(0.18), girth(0.15));
  pair(7, kLForearm, kRForearm, {0, 0, 0}, {0, -d.forearm, 0}, girth(0.165), girth(0.10));
  const double hand_r = 0.018 * H;  // between the hand's thickness and half its breadth (0.05)
  pair(9, kLHand, kRHand, {0, 0, 0}, {0, -std::max(0.0, d.hand - hand_r), 0}, hand_r, hand_r);
  pair(11, kLThigh, kRThigh, {0, 0, 0}, {0, -d.thigh, 0}, girth(0.34), girth(0.22));
  pair(13, kLCalf, kRCalf, {0, 0, 0}, {0, -d.calf, 0}, girth(0.22), girth(0.13));
  // Shoe, in the foot's frame (the calf's at ankle angle 0): from the heel, a third of the
  // ankle-to-toe length behind the ankle, to the toes, its sole on the floor.
  const double ankle_height = 0.039 * H, toe = 0.114 * H;
  const double heel_r = 0.03 * H, toe_r = 0.016 * H;
  pair(15, kLFoot, kRFoot, {0, heel_r - ankle_height, -toe / 3 + heel_r},
       {0, toe_r - ankle_height, toe - toe_r}, heel_r, toe_r);
  return s;
}

PlacedSurface place(const BodySurface& surface, const StickGeometry& g) {
  PlacedSurface out;
  for (int c = 0; c < kCapsuleCount; ++c) {
    const CapsuleShape& shape = surface[c];
    PlacedCapsule& p = out[c];
    const Eigen::Matrix3d& R = g.rotation[shape.segment];
    const Eigen::Vector3d& origin = g.proximal[shape.segment];
    p.segment = shape.segment;
    p.a = origin + R * shape.a;
    p.ab = R * (shape.b - shape.a);
    p.ra = shape.ra;
    p.dr = shape.rb - shape.ra;
    p.centre = p.a + 0.5 * p.ab;
    p.bound = 0.5 * p.ab.norm() + std::max(shape.ra, shape.rb);
  }
  return out;
}

}  // namespace simcap::tracker
