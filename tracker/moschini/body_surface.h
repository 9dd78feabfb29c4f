// The body's surface as the silhouette cues see it: tapered capsules fixed to the sticks, sized
// from typical adult proportions and then fitted to a frame whose pose is known (surface_fit.h).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <string_view>

#include "tracker/moschini/stick_model.h"

namespace simcap::tracker {

// Two capsules side by side for each part of the trunk (a round one cannot be wider than deep),
// one for the head and neck, one per limb segment, a hand after each forearm, a shoe under each
// ankle. Left and right capsules alternate in pairs, so mirrored_capsule() is arithmetic.
inline constexpr int kCapsuleCount = 17;

// A capsule whose radius changes linearly from one end of its axis to the other.
struct CapsuleShape {
  int segment = 0;
  // The axis's ends in the segment's frame, relative to its proximal joint (the hip line for
  // the pelvis).
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double ra = 0;  // radius at a
  double rb = 0;  // radius at b
};
using BodySurface = std::array<CapsuleShape, kCapsuleCount>;

std::string_view capsule_name(int capsule);
// The same capsule on the other side of the body; itself for the head.
int mirrored_capsule(int capsule);

// The standing height that sticks of these dimensions belong to (the ankle stands 3.9% of it
// above the floor, Drillis & Contini).
double stature(const BodyDimensions& dims);

// Capsules for sticks of these dimensions with an average adult's girths as fractions of
// stature (ANSUR II: thigh 0.34, calf 0.22, biceps 0.18, forearm 0.165, wrist 0.10, neck 0.22;
// chest breadth 0.175, depth 0.135; hip breadth 0.205), every axis on its stick's line.
BodySurface typical_surface(const BodyDimensions& dims);

// One capsule placed in the world.
struct PlacedCapsule {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d ab = Eigen::Vector3d::Zero();  // b - a
  double ra = 0;
  double dr = 0;  // rb - ra
  int segment = 0;
  // A sphere around the capsule: its distance bounds the capsule's from below.
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double bound = 0;

  double radius(double t) const { return ra + t * dr; }
  // The axis parameter in [0, 1] of the axis point nearest to x.
  double along(const Eigen::Vector3d& x) const {
    const double len2 = ab.squaredNorm();
    return len2 > 0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  }
  // Signed distance from x to the surface (negative inside) and the outward direction from the
  // axis there; false on the axis, where that direction is undefined. Exact for equal radii; for
  // a taper it measures across the axis, which is close for the gentle tapers of limbs. (Inline:
  // the fitting calls it for every ray and capsule it tries.)
  bool distance(const Eigen::Vector3d& x, double* d, Eigen::Vector3d* normal) const {
    const double t = along(x);
    const Eigen::Vector3d r = x - a - t * ab;
    const double n = r.norm();
    if (n < 1e-9) return false;
    *d = n - radius(t);
    *normal = r / n;
    return true;
  }
};
using PlacedSurface = std::array<PlacedCapsule, kCapsuleCount>;

PlacedSurface place(const BodySurface& surface, const StickGeometry& g);

}  // namespace simcap::tracker
