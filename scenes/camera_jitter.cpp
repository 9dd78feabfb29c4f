#include "scenes/camera_jitter.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace simcap {
namespace {

// std::seed_seq and std::mt19937_64 are specified bit for bit by the standard (the
// distributions are not), so numbers are taken from the engine's bits directly.
double uniform01(std::mt19937_64& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

}  // namespace

Camera jittered(const Camera& camera, const CameraJitter& jitter) {
  if (!jitter.any()) return camera;
  std::vector<std::uint32_t> words = {static_cast<std::uint32_t>(jitter.seed),
                                      static_cast<std::uint32_t>(jitter.seed >> 32)};
  for (const char c : camera.name) words.push_back(static_cast<unsigned char>(c));
  std::seed_seq seq(words.begin(), words.end());
  std::mt19937_64 engine(seq);
  Eigen::Vector3d shift;
  for (int i = 0; i < 3; ++i) shift[i] = jitter.position_m * (2 * uniform01(engine) - 1);
  // Axis uniform on the sphere (Archimedes: z uniform in [-1, 1], longitude uniform).
  const double z = 2 * uniform01(engine) - 1;
  const double phi = 2 * std::numbers::pi * uniform01(engine);
  const double r = std::sqrt(std::max(0.0, 1 - z * z));
  const Eigen::Vector3d axis(r * std::cos(phi), r * std::sin(phi), z);
  const double angle = jitter.rotation_deg * uniform01(engine) * std::numbers::pi / 180;
  Camera c = camera;
  const Eigen::Vector3d centre = camera.centre() + shift;
  c.R = Eigen::AngleAxisd(angle, axis).toRotationMatrix() * camera.R;
  c.t = -c.R * centre;
  return c;
}

}  // namespace simcap
