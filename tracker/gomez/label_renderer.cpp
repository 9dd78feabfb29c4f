// The capsule rasterizer (label_renderer.h).
#include "tracker/gomez/label_renderer.h"

#include <algorithm>
#include <cmath>

namespace simcap::tracker::gomez {

void render_labels(const BodyShape& shape, const std::vector<Eigen::Isometry3d>& joint_world,
                   const View& view, LabelImage& out) {
  const int W = view.width, H = view.height;
  out.width = W;
  out.height = H;
  out.cell.assign(static_cast<size_t>(W) * H, kNoCell);
  out.depth.assign(static_cast<size_t>(W) * H, INFINITY);
  out.u0 = W;
  out.v0 = H;
  out.u1 = out.v1 = 0;
  const Camera& cam = *view.camera;
  const double focal = cam.K(0, 0) / view.factor;
  for (size_t ci = 0; ci < shape.capsules.size(); ++ci) {
    const Capsule& c = shape.capsules[ci];
    const Eigen::Isometry3d& g = joint_world[c.joint];
    const Eigen::Vector3d pa = cam.to_camera(g * c.a), pb = cam.to_camera(g * c.b);
    if (pa.z() < 0.05 || pb.z() < 0.05) continue;
    const Eigen::Vector2d a = view.to_working(cam.project_camera(pa));
    const Eigen::Vector2d b = view.to_working(cam.project_camera(pb));
    const double ra = focal * c.ra / pa.z(), rb = focal * c.rb / pb.z();
    const int u_lo = std::max(0, static_cast<int>(std::floor(std::min(a.x() - ra, b.x() - rb))));
    const int u_hi = std::min(W, static_cast<int>(std::ceil(std::max(a.x() + ra, b.x() + rb))) + 1);
    const int v_lo = std::max(0, static_cast<int>(std::floor(std::min(a.y() - ra, b.y() - rb))));
    const int v_hi = std::min(H, static_cast<int>(std::ceil(std::max(a.y() + ra, b.y() + rb))) + 1);
    if (u_lo >= u_hi || v_lo >= v_hi) continue;
    const Eigen::Vector2d ab = b - a;
    const double length2 = ab.squaredNorm();
    const double inv_length2 = length2 > 1e-12 ? 1.0 / length2 : 0.0;
    const double dr = rb - ra, dz = pb.z() - pa.z(), dm = c.rb - c.ra;
    const std::uint8_t first_cell = static_cast<std::uint8_t>(ci * kCellsPerCapsule);
    // The face's direction in camera coordinates; a pixel's outward normal there is about
    // (e / r, -bulge) (across the sight line, then towards the camera).
    const bool faced = c.front.squaredNorm() > 0;
    const Eigen::Vector3d front = cam.R * (g.linear() * c.front);
    bool drew = false;
    for (int v = v_lo; v < v_hi; ++v) {
      const double py = v - a.y();
      for (int u = u_lo; u < u_hi; ++u) {
        const double px = u - a.x();
        const double t = std::clamp((px * ab.x() + py * ab.y()) * inv_length2, 0.0, 1.0);
        const double ex = px - t * ab.x(), ey = py - t * ab.y();
        const double d2 = ex * ex + ey * ey;
        const double r = ra + t * dr;
        if (d2 > r * r) continue;
        // Front surface: the axis depth less the radius where the sight line crosses it.
        const double bulge = std::sqrt(std::max(0.0, 1.0 - d2 / (r * r)));
        const float z = static_cast<float>(pa.z() + t * dz - (c.ra + t * dm) * bulge);
        const size_t i = static_cast<size_t>(v) * W + u;
        if (z >= out.depth[i]) continue;
        out.depth[i] = z;
        const bool back = faced && (ex * front.x() + ey * front.y()) / r < bulge * front.z();
        out.cell[i] = static_cast<std::uint8_t>(
            first_cell +
            (back ? kCellsPerCapsule - 1
                  : std::min(kCellsPerCapsule - 1, static_cast<int>(t * kCellsPerCapsule))));
        drew = true;
      }
    }
    if (drew) {
      out.u0 = std::min(out.u0, u_lo);
      out.u1 = std::max(out.u1, u_hi);
      out.v0 = std::min(out.v0, v_lo);
      out.v1 = std::max(out.v1, v_hi);
    }
  }
  if (out.u0 >= out.u1) out.u0 = out.u1 = out.v0 = out.v1 = 0;
}

Eigen::AlignedBox2d body_extent(const BodyShape& shape,
                                const std::vector<Eigen::Isometry3d>& joint_world,
                                const Camera& camera) {
  Eigen::AlignedBox2d box;
  for (const Capsule& c : shape.capsules) {
    for (const auto& [end, radius] : {std::pair{c.a, c.ra}, std::pair{c.b, c.rb}}) {
      const Eigen::Vector3d p = camera.to_camera(joint_world[c.joint] * end);
      if (p.z() < 0.05) continue;
      const Eigen::Vector2d q = camera.project_camera(p);
      const double r = camera.K(0, 0) * radius / p.z();
      box.extend(q - Eigen::Vector2d::Constant(r));
      box.extend(q + Eigen::Vector2d::Constant(r));
    }
  }
  return box;
}

cv::Rect body_box(const BodyShape& shape, const std::vector<Eigen::Isometry3d>& joint_world,
                  const Camera& camera) {
  const Eigen::AlignedBox2d box = body_extent(shape, joint_world, camera);
  if (box.isEmpty() || !(box.max().x() > box.min().x()) || !(box.max().y() > box.min().y())) {
    return {};
  }
  const auto lo = [](double v) { return static_cast<int>(std::floor(std::clamp(v, -1e6, 1e6))); };
  const auto hi = [](double v) { return static_cast<int>(std::ceil(std::clamp(v, -1e6, 1e6))); };
  const double x0 = box.min().x(), y0 = box.min().y(), x1 = box.max().x(), y1 = box.max().y();
  return {lo(x0), lo(y0), hi(x1) - lo(x0) + 1, hi(y1) - lo(y0) + 1};
}

}  // namespace simcap::tracker::gomez
