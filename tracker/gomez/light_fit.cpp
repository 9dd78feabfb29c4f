// The shading light's fit on the first frame (light_fit.h).
#include "tracker/gomez/light_fit.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker::gomez {

std::vector<ShadedPixel> shaded_pixels(const BodyShape& shape,
                                       const std::vector<Eigen::Isometry3d>& world,
                                       const View& view, const LabelImage& cells,
                                       const cv::Mat& image, const cv::Mat& silhouette,
                                       const std::vector<std::uint8_t>& cell_class, double rim) {
  std::vector<ShadedPixel> out;
  const Camera& camera = *view.camera;
  const double focal = camera.K(0, 0) / view.factor;
  const cv::Rect box(view.x0, view.y0, view.width * view.factor, view.height * view.factor);
  cv::Mat grey;
  cv::cvtColor(image(box), grey, cv::COLOR_BGR2GRAY);
  for (int v = cells.v0; v < cells.v1; ++v) {
    for (int u = cells.u0; u < cells.u1; ++u) {
      const std::uint8_t cell = cells.at(u, v);
      if (cell == kNoCell || !silhouette.at<std::uint8_t>(view.y0 + v, view.x0 + u)) continue;
      // The pixel's offset e from the capsule's projected axis, whose radius there is r: the
      // normal is e / r across the sight line and sqrt(1 - |e|^2 / r^2) towards the camera.
      const Capsule& c = shape.capsules[cell / kCellsPerCapsule];
      const Eigen::Isometry3d& g = world[c.joint];
      const Eigen::Vector3d pa = camera.to_camera(g * c.a), pb = camera.to_camera(g * c.b);
      const Eigen::Vector2d a = view.to_working(camera.project_camera(pa));
      const Eigen::Vector2d ab = view.to_working(camera.project_camera(pb)) - a;
      const Eigen::Vector2d p = Eigen::Vector2d(u, v) - a;
      const double length2 = ab.squaredNorm();
      const double t = length2 > 1e-12 ? std::clamp(p.dot(ab) / length2, 0.0, 1.0) : 0.0;
      const Eigen::Vector2d e =
          (p - t * ab) / (focal * (c.ra / pa.z() + t * (c.rb / pb.z() - c.ra / pa.z())));
      if (e.norm() > rim) continue;
      out.push_back({Eigen::Vector3d(e.x(), e.y(), -std::sqrt(1 - e.squaredNorm())),
                     cell_class[cell], static_cast<double>(grey.at<std::uint8_t>(v, u))});
    }
  }
  return out;
}

namespace {

// The best direction of the lattice for `pixels`, with each class's line; `lowest` its summed
// squared residual (infinite when no direction is admissible).
Lighting search_light(const std::vector<const ShadedPixel*>& pixels, const Eigen::Vector3d& up,
                      int directions, double& lowest) {
  Lighting best;
  lowest = INFINITY;
  // A Fibonacci lattice: `directions` points of nearly equal spacing on the hemisphere about up.
  const Eigen::Vector3d w = up.normalized();
  const Eigen::Vector3d e1 = w.unitOrthogonal(), e2 = w.cross(e1);
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int k = 0; k < directions; ++k) {
    const double y = 1 - (k + 0.5) / directions, r = std::sqrt(1 - y * y);
    const Eigen::Vector3d l = y * w + r * std::cos(golden * k) * e1 + r * std::sin(golden * k) * e2;
    // Per class: sums of x = max(0, n . l) and y = grey for the line y = a x + b.
    struct Sums {
      double n = 0, x = 0, y = 0, xx = 0, xy = 0, yy = 0;
    };
    std::array<Sums, kMaxColourClasses + 1> sums{};
    for (const ShadedPixel* p : pixels) {
      const double x = std::max(0.0, p->normal.dot(l));
      Sums& m = sums[p->cls];
      m.n += 1;
      m.x += x;
      m.y += p->grey;
      m.xx += x * x;
      m.xy += x * p->grey;
      m.yy += p->grey * p->grey;
    }
    Lighting lighting;
    lighting.to_light = l;
    double residual = 0;
    bool admissible = true;
    for (int c = 0; c <= kMaxColourClasses; ++c) {
      const Sums& m = sums[c];
      if (m.n == 0) continue;
      const double spread = m.n * m.xx - m.x * m.x;
      const double a = spread > 1e-12 ? std::max(0.0, (m.n * m.xy - m.x * m.y) / spread) : 0.0;
      const double b = (m.y - a * m.x) / m.n;
      // No negative ambient, and no class brighter than white where the light meets it head-on:
      // a grazing light would fit small grey differences with a huge albedo.
      admissible = admissible && b >= 0 && a + b <= 255;
      lighting.albedo[c] = a;
      lighting.offset[c] = b;
      residual += m.yy - 2 * a * m.xy - 2 * b * m.y + a * a * m.xx + 2 * a * b * m.x + m.n * b * b;
    }
    if (admissible && residual < lowest) {
      lowest = residual;
      best = lighting;
    }
  }
  return best;
}

}  // namespace

LightFit fit_light(const std::vector<ShadedPixel>& pixels, const Eigen::Vector3d& up,
                   int directions) {
  LightFit fit;
  if (pixels.empty()) return fit;
  std::vector<const ShadedPixel*> used;
  for (const ShadedPixel& p : pixels) used.push_back(&p);
  double lowest = INFINITY;
  fit.lighting = search_light(used, up, directions, lowest);
  if (!fit.lighting.known()) return fit;
  // Again without the pixels the first fit misses by more than twice its rms: cast shadows (an
  // arm's on the trunk, the head's on a shoulder) and the capsules' wrong normals where the body
  // is not round.
  const double rms = std::sqrt(std::max(0.0, lowest) / static_cast<double>(used.size()));
  std::vector<const ShadedPixel*> inliers;
  for (const ShadedPixel* p : used) {
    const double x = std::max(0.0, p->normal.dot(fit.lighting.to_light));
    const double miss = p->grey - fit.lighting.albedo[p->cls] * x - fit.lighting.offset[p->cls];
    if (std::abs(miss) <= 2 * rms) inliers.push_back(p);
  }
  const Lighting refined = search_light(inliers, up, directions, lowest);
  if (refined.known()) {
    fit.lighting = refined;
    fit.pixels = static_cast<int>(inliers.size());
    fit.rms_grey = std::sqrt(std::max(0.0, lowest) / static_cast<double>(inliers.size()));
  }
  return fit;
}

}  // namespace simcap::tracker::gomez
