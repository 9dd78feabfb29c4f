#include "models/generalized_cylinder.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace simcap {
namespace {

// Monotone piecewise-cubic Hermite interpolation (Fritsch & Carlson 1980) of one section field.
class MonotoneCubic {
 public:
  MonotoneCubic(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    const size_t n = x_.size();
    slope_.assign(n, 0.0);
    if (n < 2) return;
    std::vector<double> secant(n - 1);
    for (size_t i = 0; i + 1 < n; ++i) secant[i] = (y_[i + 1] - y_[i]) / (x_[i + 1] - x_[i]);
    slope_[0] = secant[0];
    slope_[n - 1] = secant[n - 2];
    for (size_t i = 1; i + 1 < n; ++i) {
      // Zero slope at local extrema keeps the curve within its keys.
      if (secant[i - 1] * secant[i] <= 0.0) continue;
      const double w1 = 2 * (x_[i + 1] - x_[i]) + (x_[i] - x_[i - 1]);
      const double w2 = (x_[i + 1] - x_[i]) + 2 * (x_[i] - x_[i - 1]);
      slope_[i] = (w1 + w2) / (w1 / secant[i - 1] + w2 / secant[i]);
    }
  }

  double operator()(double x) const {
    if (x_.size() == 1 || x <= x_.front()) return y_.front();
    if (x >= x_.back()) return y_.back();
    const size_t i = std::upper_bound(x_.begin(), x_.end(), x) - x_.begin() - 1;
    const double h = x_[i + 1] - x_[i];
    const double t = (x - x_[i]) / h;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y_[i] + (t3 - 2 * t2 + t) * h * slope_[i] +
           (-2 * t3 + 3 * t2) * y_[i + 1] + (t3 - t2) * h * slope_[i + 1];
  }

 private:
  std::vector<double> x_, y_, slope_;
};

// Every field of the section keys interpolated along s.
class SectionCurve {
 public:
  explicit SectionCurve(const std::vector<TubeSection>& keys) {
    std::vector<double> s;
    std::array<std::vector<double>, 6> values;
    for (const TubeSection& k : keys) {
      s.push_back(k.s);
      const double fields[6] = {k.half_u,     k.half_v,     k.offset.x(),
                                k.offset.y(), k.offset.z(), k.exponent};
      for (int f = 0; f < 6; ++f) values[f].push_back(fields[f]);
    }
    for (int f = 0; f < 6; ++f) fields_.emplace_back(s, values[f]);
  }

  TubeSection operator()(double s) const {
    TubeSection out;
    out.s = s;
    out.half_u = fields_[0](s);
    out.half_v = fields_[1](s);
    out.offset = {fields_[2](s), fields_[3](s), fields_[4](s)};
    out.exponent = fields_[5](s);
    return out;
  }

 private:
  std::vector<MonotoneCubic> fields_;
};

// Point and unit direction of a polyline at arc length s. The direction is the chord over
// +-`smoothing`, so rings turn gradually through a bend instead of flipping at the corner.
class Polyline {
 public:
  explicit Polyline(const std::vector<Eigen::Vector3d>& points) : points_(points) {
    cumulative_.push_back(0.0);
    for (size_t i = 1; i < points_.size(); ++i) {
      cumulative_.push_back(cumulative_.back() + (points_[i] - points_[i - 1]).norm());
    }
  }
  double length() const { return cumulative_.back(); }

  Eigen::Vector3d point(double s) const {
    s = std::clamp(s, 0.0, length());
    size_t i = std::upper_bound(cumulative_.begin(), cumulative_.end(), s) - cumulative_.begin();
    i = std::clamp<size_t>(i, 1, points_.size() - 1);
    const double span = cumulative_[i] - cumulative_[i - 1];
    const double t = span > 0 ? (s - cumulative_[i - 1]) / span : 0.0;
    return points_[i - 1] + t * (points_[i] - points_[i - 1]);
  }

  Eigen::Vector3d direction(double s, double smoothing) const {
    const double a = std::max(0.0, s - smoothing), b = std::min(length(), s + smoothing);
    return (point(b) - point(a)).normalized();
  }

 private:
  std::vector<Eigen::Vector3d> points_;
  std::vector<double> cumulative_;
};

// Superellipse |x/a|^e + |y/b|^e = 1 at angle theta (e = 2: the ellipse).
Eigen::Vector2d superellipse(double theta, double exponent) {
  const double c = std::cos(theta), s = std::sin(theta);
  const double p = 2.0 / exponent;
  return {std::copysign(std::pow(std::abs(c), p), c), std::copysign(std::pow(std::abs(s), p), s)};
}

void check_spec(const TubeSpec& spec, double length) {
  auto fail = [](const std::string& what) { throw Error("body mesh tube: " + what); };
  if (spec.axis.size() < 2) fail("the axis needs at least two points");
  if (spec.sections.empty()) fail("no cross-section keys");
  if (spec.segments < 3 || spec.cap_rings < 1 || !(spec.ring_spacing > 0)) {
    fail("segments, cap_rings and ring_spacing must be positive");
  }
  if (!(spec.start_cap > 0) || !(spec.end_cap > 0) || spec.start_cap + spec.end_cap >= length) {
    fail("the end caps must be positive and shorter than the axis together");
  }
  constexpr double kTolerance = 1e-9;
  if (std::abs(spec.sections.front().s - spec.start_cap) > kTolerance ||
      std::abs(spec.sections.back().s - (length - spec.end_cap)) > kTolerance) {
    fail("the first and last keys must sit where the caps begin");
  }
  for (size_t i = 0; i < spec.sections.size(); ++i) {
    const TubeSection& k = spec.sections[i];
    if (!(k.half_u > 0) || !(k.half_v > 0) || !(k.exponent >= 1)) {
      fail("key " + std::to_string(i) + " has a non-positive size or an exponent below 1");
    }
    if (i > 0 && !(k.s > spec.sections[i - 1].s)) fail("keys are not in increasing s");
  }
}

}  // namespace

TubeSurface build_tube(const TubeSpec& spec) {
  const Polyline axis(spec.axis);
  check_spec(spec, axis.length());
  const SectionCurve curve(spec.sections);
  const double body_begin = spec.start_cap, body_end = axis.length() - spec.end_cap;

  // Rings as (arc length, section, scale); the domes reuse the section where they begin, scaled
  // by sin(phi) at s = cap (1 - cos(phi)), which makes each end a half-ellipsoid.
  struct Ring {
    double s;
    TubeSection section;
    double scale;
  };
  std::vector<Ring> rings;
  const double half_pi = 0.5 * std::numbers::pi;
  const TubeSection first = curve(body_begin), last = curve(body_end);
  for (int k = 1; k < spec.cap_rings; ++k) {
    const double phi = half_pi * k / spec.cap_rings;
    rings.push_back({spec.start_cap * (1 - std::cos(phi)), first, std::sin(phi)});
  }
  const int body_rings =
      std::max(2, static_cast<int>(std::ceil((body_end - body_begin) / spec.ring_spacing)) + 1);
  for (int k = 0; k < body_rings; ++k) {
    const double s = body_begin + (body_end - body_begin) * k / (body_rings - 1);
    rings.push_back({s, curve(s), 1.0});
  }
  for (int k = spec.cap_rings - 1; k >= 1; --k) {
    const double phi = half_pi * k / spec.cap_rings;
    rings.push_back({axis.length() - spec.end_cap * (1 - std::cos(phi)), last, std::sin(phi)});
  }

  TubeSurface out;
  const double smoothing = 2.0 * spec.ring_spacing;
  const Eigen::Vector3d start_pole = axis.point(0.0) + first.offset;
  out.vertices.push_back(start_pole);
  out.vertex_s.push_back(0.0);
  for (const Ring& ring : rings) {
    const Eigen::Vector3d t = axis.direction(ring.s, smoothing);
    Eigen::Vector3d u = spec.reference - spec.reference.dot(t) * t;
    if (u.norm() < 1e-6) throw Error("body mesh tube: reference direction parallel to the axis");
    u.normalize();
    const Eigen::Vector3d v = t.cross(u);
    const Eigen::Vector3d centre = axis.point(ring.s) + ring.section.offset;
    for (int j = 0; j < spec.segments; ++j) {
      const double theta = 2.0 * std::numbers::pi * j / spec.segments;
      const Eigen::Vector2d q = superellipse(theta, ring.section.exponent);
      out.vertices.push_back(centre + ring.scale * (q.x() * ring.section.half_u * u +
                                                    q.y() * ring.section.half_v * v));
      out.vertex_s.push_back(ring.s);
    }
  }
  out.vertices.push_back(axis.point(axis.length()) + last.offset);
  out.vertex_s.push_back(axis.length());

  // With u x v = t and theta increasing from u towards v, (j, j+1, next ring) turns
  // counter-clockwise seen from outside.
  const auto n = static_cast<std::uint32_t>(spec.segments);
  const auto ring_count = static_cast<std::uint32_t>(rings.size());
  auto at = [n](std::uint32_t ring, std::uint32_t j) { return 1 + ring * n + j % n; };
  for (std::uint32_t j = 0; j < n; ++j) out.triangles.push_back({0, at(0, j + 1), at(0, j)});
  for (std::uint32_t r = 0; r + 1 < ring_count; ++r) {
    for (std::uint32_t j = 0; j < n; ++j) {
      out.triangles.push_back({at(r, j), at(r, j + 1), at(r + 1, j + 1)});
      out.triangles.push_back({at(r, j), at(r + 1, j + 1), at(r + 1, j)});
    }
  }
  const auto end_pole = static_cast<std::uint32_t>(out.vertices.size() - 1);
  for (std::uint32_t j = 0; j < n; ++j) {
    out.triangles.push_back({end_pole, at(ring_count - 1, j), at(ring_count - 1, j + 1)});
  }
  return out;
}

}  // namespace simcap
