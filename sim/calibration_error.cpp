#include "sim/calibration_error.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "sim/random.h"

namespace simcap {
namespace {

enum Stream : std::uint64_t { kAxis = 21, kShift = 22, kFocal = 23, kPrincipal = 24 };

// Uniform on the unit sphere (Archimedes: z uniform in [-1, 1], longitude uniform).
Eigen::Vector3d unit_vector(std::uint64_t bits) {
  const double z = 2.0 * uniform01(bits) - 1.0;
  const double phi = 2.0 * std::numbers::pi * uniform01(mix64(bits));
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

}  // namespace

CameraPerturbation camera_perturbation(const CalibrationError& error, const std::string& name) {
  const std::uint64_t key = text_key(name);
  CameraPerturbation p;
  p.rotation_axis = unit_vector(random_bits(error.seed, {kAxis, key}));
  p.rotation_deg = error.rotation_deg;
  p.centre_shift_m = error.translation_m * unit_vector(random_bits(error.seed, {kShift, key}));
  const bool larger = (random_bits(error.seed, {kFocal, key}) >> 63) != 0;
  p.focal_scale = 1.0 + (larger ? error.focal_rel : -error.focal_rel);
  const double angle =
      2.0 * std::numbers::pi * uniform01(random_bits(error.seed, {kPrincipal, key}));
  p.principal_shift_px = error.principal_px * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  return p;
}

Camera perturb(const Camera& camera, const CameraPerturbation& p) {
  Camera c = camera;
  const Eigen::Vector3d centre = camera.centre() + p.centre_shift_m;
  c.R = Eigen::AngleAxisd(p.rotation_deg * std::numbers::pi / 180.0, p.rotation_axis)
            .toRotationMatrix() *
        camera.R;
  c.t = -c.R * centre;
  c.K(0, 0) *= p.focal_scale;
  c.K(1, 1) *= p.focal_scale;
  c.K(0, 2) += p.principal_shift_px.x();
  c.K(1, 2) += p.principal_shift_px.y();
  return c;
}

std::vector<Camera> written_calibration(const std::vector<Camera>& cameras,
                                        const CalibrationError& error) {
  if (!error.any()) return cameras;
  std::vector<Camera> out;
  for (const Camera& c : cameras) out.push_back(perturb(c, camera_perturbation(error, c.name)));
  return out;
}

}  // namespace simcap
