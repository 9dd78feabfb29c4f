// The arm bones' Lambert shading (bone_shading.h).
#include "tracker/gomez/bone_shading.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace simcap::tracker::gomez {

double lambert_cylinder_mean(const Eigen::Vector3d& axis, const Eigen::Vector3d& to_camera,
                             const Eigen::Vector3d& to_light) {
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d across = to_camera - to_camera.dot(a) * a;
  if (across.norm() < 1e-9 * to_camera.norm()) {
    return std::max(0.0, to_camera.normalized().dot(to_light));
  }
  // Visible normals n(p) = cos p e1 + sin p e2, p in [-pi/2, pi/2], projected width cos p; the
  // light's part across the axis is rho (cos q, sin q), lit where |p - q| < pi/2. The mean is
  // rho/2 times the integral of cos p cos(p - q) over both ranges, whose antiderivative is
  // sin(2p - q)/4 + p cos(q)/2.
  const Eigen::Vector3d e1 = across.normalized(), e2 = a.cross(e1);
  const double l1 = to_light.dot(e1), l2 = to_light.dot(e2);
  const double rho = std::hypot(l1, l2);
  if (rho < 1e-12) return 0.0;
  const double q = std::atan2(l2, l1), half = std::numbers::pi / 2;
  const double lo = std::max(-half, q - half), hi = std::min(half, q + half);
  const auto F = [q](double p) { return 0.25 * std::sin(2 * p - q) + 0.5 * p * std::cos(q); };
  return 0.5 * rho * (F(hi) - F(lo));
}

BoneShading::BoneShading(const BodyShape& shape, const Skeleton& skeleton,
                         const std::vector<std::uint8_t>& cell_class) {
  cell_bone_.assign(cell_class.size(), -1);
  const char* joints[kShadedBones] = {"l_shoulder", "l_elbow", "r_shoulder", "r_elbow"};
  for (int b = 0; b < kShadedBones; ++b) {
    for (size_t c = 0; c < shape.capsules.size(); ++c) {
      if (skeleton[shape.capsules[c].joint].name == joints[b]) capsule_[b] = static_cast<int>(c);
    }
    if (capsule_[b] < 0) {
      capsule_.fill(-1);
      return;
    }
    bone_[b] = shape.capsules[capsule_[b]];
    const size_t first = static_cast<size_t>(capsule_[b]) * kCellsPerCapsule;
    std::array<int, 256> votes{};
    for (int k = 0; k < kCellsPerCapsule; ++k) ++votes[cell_class[first + k]];
    class_[b] =
        static_cast<std::uint8_t>(std::max_element(votes.begin() + 1, votes.end()) - votes.begin());
    for (int k = 0; k < kCellsPerCapsule; ++k) {
      if (cell_class[first + k] == class_[b]) cell_bone_[first + k] = static_cast<std::int8_t>(b);
    }
  }
}

std::array<BoneSample, kShadedBones> BoneShading::observe(
    const LabelImage& labels, const std::vector<Eigen::Isometry3d>& world,
    const FrameCues& cues) const {
  std::array<BoneSample, kShadedBones> out;
  if (!available()) return out;
  std::array<long, kShadedBones> sum{};
  // A pixel on the silhouette's outline mixes the background's colour into the bone's (a thin
  // arm at working resolution is mostly outline): only pixels whose four neighbours are inside
  // count.
  const int W = labels.width, H = labels.height;
  const auto interior = [&](int u, int v) {
    const size_t i = static_cast<size_t>(v) * W + u;
    return u > 0 && v > 0 && u + 1 < W && v + 1 < H && cues.cls[i - 1] && cues.cls[i + 1] &&
           cues.cls[i - W] && cues.cls[i + W];
  };
  for (int v = labels.v0; v < labels.v1; ++v) {
    const size_t row = static_cast<size_t>(v) * labels.width;
    for (int u = labels.u0; u < labels.u1; ++u) {
      const std::uint8_t cell = labels.cell[row + u];
      if (cell == kNoCell) continue;
      const int b = cell_bone_[cell];
      if (b < 0 || cues.cls[row + u] != class_[b] || !interior(u, v)) continue;
      sum[b] += cues.grey[row + u];
      ++out[b].pixels;
    }
  }
  const Camera& camera = *cues.view.camera;
  for (int b = 0; b < kShadedBones; ++b) {
    const Capsule& c = bone_[b];
    const Eigen::Vector3d pa = camera.to_camera(world[c.joint] * c.a);
    const Eigen::Vector3d pb = camera.to_camera(world[c.joint] * c.b);
    out[b].axis = pb - pa;
    out[b].to_camera = -0.5 * (pa + pb);
    out[b].cls = class_[b];
    out[b].grey = out[b].pixels ? static_cast<double>(sum[b]) / out[b].pixels : 0.0;
  }
  return out;
}

double predicted_grey(const BoneSample& bone, const Lighting& lighting) {
  return lighting.albedo[bone.cls] *
             lambert_cylinder_mean(bone.axis, bone.to_camera, lighting.to_light) +
         lighting.offset[bone.cls];
}

BoneSample depth_flip(const BoneSample& bone) {
  BoneSample out = bone;
  const Eigen::Vector3d v = bone.to_camera.normalized();
  out.axis = bone.axis - 2 * bone.axis.dot(v) * v;
  return out;
}

double flip_penalty(const std::array<BoneSample, kShadedBones>& bones, const Lighting& lighting) {
  double sum = 0;
  for (const BoneSample& b : bones) {
    if (b.pixels < BoneShading::kMinPixels) continue;
    const double r = b.grey - predicted_grey(b, lighting);
    const double f = b.grey - predicted_grey(depth_flip(b), lighting);
    sum += std::max(0.0, r * r - f * f);
  }
  return sum;
}

}  // namespace simcap::tracker::gomez
