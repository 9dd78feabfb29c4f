// A closed tube swept along a polyline: rings with varying superelliptic cross-sections and a dome
// at each end, meshed as one watertight, outward-oriented triangle surface (a body-mesh part).
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

namespace simcap {

// The cross-section at arc length `s` along the tube's axis. Rings between keys are interpolated
// with a monotone cubic, so a key never causes an overshoot.
struct TubeSection {
  double s = 0.0;       // arc length along the axis polyline, metres
  double half_u = 0.0;  // semi-axis along the ring's u direction, metres
  double half_v = 0.0;  // semi-axis along v = tangent x u, metres
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // ring centre minus axis point (world)
  double exponent = 2.0;  // superellipse exponent: 2 is an ellipse, larger is boxier
};

struct TubeSpec {
  // Axis polyline; its first and last points are the poles of the two domes.
  std::vector<Eigen::Vector3d> axis;
  // A ring's u direction is this vector made perpendicular to the local axis direction.
  Eigen::Vector3d reference = Eigen::Vector3d::UnitX();
  // Keys in increasing s; the first lies at s = start_cap, the last at s = length - end_cap.
  std::vector<TubeSection> sections;
  double start_cap = 0.0;  // dome lengths at the two ends, metres (> 0)
  double end_cap = 0.0;
  int segments = 32;           // vertices per ring
  double ring_spacing = 0.01;  // approximate distance between rings, metres
  int cap_rings = 6;           // rings per dome, pole excluded
};

struct TubeSurface {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<double> vertex_s;  // arc length of the ring (or pole) each vertex lies on
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
};

// Meshes the tube. Throws Error when the spec is inconsistent (too few axis points, keys out of
// order or outside the caps, non-positive sizes).
TubeSurface build_tube(const TubeSpec& spec);

}  // namespace simcap
