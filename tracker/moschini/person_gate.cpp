#include "tracker/moschini/person_gate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace simcap::tracker {

namespace {

// Signed distance from x to the nearest capsule of the body (negative inside).
double body_distance(const PlacedSurface& body, const Eigen::Vector3d& x) {
  double best = std::numeric_limits<double>::infinity();
  for (const PlacedCapsule& c : body) {
    if ((x - c.centre).norm() - c.bound >= best) continue;
    const double t = c.along(x);
    best = std::min(best, (x - c.a - t * c.ab).norm() - c.radius(t));
  }
  return best;
}

// Paints into `mask` each capsule of the body, widened by `margin`, as a thick segment between
// its ends' projections (the radius taken at the nearer end's depth).
void paint_body(const Camera& cam, const PlacedSurface& body, double margin, cv::Mat& mask) {
  for (const PlacedCapsule& capsule : body) {
    const Eigen::Vector3d qa = cam.to_camera(capsule.a), qb = cam.to_camera(capsule.a + capsule.ab);
    const double z = std::min(qa.z(), qb.z());
    if (z <= 0.05) continue;
    const double r = (std::max(capsule.ra, capsule.ra + capsule.dr) + margin) * cam.K(0, 0) / z;
    const Eigen::Vector2d pa = cam.project_camera(qa), pb = cam.project_camera(qb);
    const cv::Point a(static_cast<int>(std::lround(pa.x())), static_cast<int>(std::lround(pa.y())));
    const cv::Point b(static_cast<int>(std::lround(pb.x())), static_cast<int>(std::lround(pb.y())));
    const int radius = static_cast<int>(std::ceil(r));
    cv::line(mask, a, b, cv::Scalar(255), 2 * radius + 1);
    cv::circle(mask, a, radius, cv::Scalar(255), cv::FILLED);
    cv::circle(mask, b, radius, cv::Scalar(255), cv::FILLED);
  }
}

// Calls draw(pixel, radius, depth) for the image of each voxel: a disc of about its circumscribed
// sphere's image at the sphere's nearest depth.
template <typename Draw>
void each_voxel(const Camera& cam, const std::vector<Eigen::Vector3d>& centres,
                double half_diagonal, Draw draw) {
  for (const Eigen::Vector3d& p : centres) {
    const Eigen::Vector3d q = cam.to_camera(p);
    if (q.z() <= half_diagonal) continue;
    draw(cam.project_camera(q), half_diagonal * cam.K(0, 0) / q.z(), q.z() - half_diagonal);
  }
}

// Paints into `mask` the image of each voxel (its disc widened by a pixel, so that neighbouring
// discs leave no cracks).
void paint_voxels(const Camera& cam, const std::vector<Eigen::Vector3d>& centres,
                  double half_diagonal, cv::Mat& mask) {
  each_voxel(cam, centres, half_diagonal, [&](const Eigen::Vector2d& px, double r, double) {
    cv::circle(
        mask,
        cv::Point(static_cast<int>(std::lround(px.x())), static_cast<int>(std::lround(px.y()))),
        static_cast<int>(std::ceil(r)) + 1, cv::Scalar(255), cv::FILLED);
  });
}

// Lowers `depth` (CV_32F, camera z in metres) to `z` over the disc of `radius` pixels at `px`.
void splat_depth(cv::Mat& depth, const Eigen::Vector2d& px, double radius, double z) {
  const int r = static_cast<int>(std::ceil(radius));
  const int cu = static_cast<int>(std::lround(px.x())), cw = static_cast<int>(std::lround(px.y()));
  const float zf = static_cast<float>(z);
  for (int v = std::max(0, cw - r); v <= std::min(depth.rows - 1, cw + r); ++v) {
    float* row = depth.ptr<float>(v);
    for (int u = std::max(0, cu - r); u <= std::min(depth.cols - 1, cu + r); ++u) {
      if ((u - cu) * (u - cu) + (v - cw) * (v - cw) <= radius * radius)
        row[u] = std::min(row[u], zf);
    }
  }
}

// Lowers `depth` to the voxels' nearest depth where they project.
void voxel_depth(const Camera& cam, const std::vector<Eigen::Vector3d>& centres,
                 double half_diagonal, cv::Mat& depth) {
  each_voxel(cam, centres, half_diagonal, [&](const Eigen::Vector2d& px, double r, double z) {
    splat_depth(depth, px, r + 1, z);
  });
}

// Lowers `depth` to the body's nearest depth where its capsules, widened by `margin`, project:
// spheres along each capsule's axis a voxel's step apart, each at its front's depth.
void body_depth(const Camera& cam, const PlacedSurface& body, double margin, double step,
                cv::Mat& depth) {
  for (const PlacedCapsule& c : body) {
    const int n = std::max(1, static_cast<int>(std::ceil(c.ab.norm() / step)));
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n, r = c.radius(t);
      const Eigen::Vector3d q = cam.to_camera(c.a + t * c.ab);
      if (q.z() <= r + 0.05) continue;
      splat_depth(depth, cam.project_camera(q), (r + margin) * cam.K(0, 0) / q.z(), q.z() - r);
    }
  }
}

// Per cell of the hull's box, the distance in voxels (Chebyshev) to the nearest of `points` that
// lie inside the box, up to `limit`; farther cells hold limit + 1.
std::vector<int> steps_to(const Occupancy& hull, const std::vector<Eigen::Vector3d>& points,
                          int limit) {
  const Eigen::Vector3i& n = hull.size;
  std::vector<int> steps(hull.cells.size(), limit + 1);
  std::vector<int> queue;
  for (const Eigen::Vector3d& p : points) {
    const Eigen::Vector3i r = hull.grid.index(p) - hull.lo;
    if ((r.array() < 0).any() || (r.array() >= n.array()).any()) continue;
    const int i = (r.y() * n.z() + r.z()) * n.x() + r.x();
    if (steps[i] == 0) continue;
    steps[i] = 0;
    queue.push_back(i);
  }
  for (size_t q = 0; q < queue.size(); ++q) {
    const int i = queue[q];
    if (steps[i] >= limit) continue;
    const int cx = i % n.x(), cz = (i / n.x()) % n.z(), cy = i / (n.x() * n.z());
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int ax = cx + dx, ay = cy + dy, az = cz + dz;
          if (ax < 0 || ay < 0 || az < 0 || ax >= n.x() || ay >= n.y() || az >= n.z()) continue;
          const int j = (ay * n.z() + az) * n.x() + ax;
          if (steps[j] > steps[i] + 1) {
            steps[j] = steps[i] + 1;
            queue.push_back(j);
          }
        }
      }
    }
  }
  return steps;
}

}  // namespace

PersonGate::PersonGate(std::vector<Camera> cameras, const GateOptions& options)
    : cameras_(std::move(cameras)), options_(options) {}

GateResult PersonGate::restrict(const Occupancy& hull, const PlacedSurface& body,
                                std::vector<cv::Mat>& silhouettes, std::vector<cv::Mat>* cover,
                                const std::vector<cv::Mat>* distinct,
                                const std::vector<Eigen::Vector3d>* others_before) const {
  GateResult result;
  const Eigen::Vector3i& n = hull.size;
  const auto cell = [&](int x, int y, int z) { return (y * n.z() + z) * n.x() + x; };
  // Label the components (26-neighbourhood) with a breadth-first flood.
  std::vector<int> label(hull.cells.size(), -1);
  std::vector<int> queue;
  std::vector<double> distance(hull.cells.size(), 0.0);
  struct Component {
    int size = 0;
    int beyond_reach = 0;
    double nearest = std::numeric_limits<double>::infinity();
  };
  std::vector<Component> components;
  for (int y = 0; y < n.y(); ++y) {
    for (int z = 0; z < n.z(); ++z) {
      for (int x = 0; x < n.x(); ++x) {
        const int start = cell(x, y, z);
        if (!hull.cells[start] || label[start] >= 0) continue;
        const int id = static_cast<int>(components.size());
        Component& comp = components.emplace_back();
        label[start] = id;
        queue.assign(1, start);
        for (size_t q = 0; q < queue.size(); ++q) {
          const int i = queue[q];
          const int cx = i % n.x(), cz = (i / n.x()) % n.z(), cy = i / (n.x() * n.z());
          const Eigen::Vector3d p = hull.grid.center(hull.lo + Eigen::Vector3i(cx, cy, cz));
          const double d = body_distance(body, p);
          distance[i] = d;
          ++comp.size;
          comp.nearest = std::min(comp.nearest, d);
          if (d > options_.reach_m) ++comp.beyond_reach;
          for (int dy = -1; dy <= 1; ++dy) {
            for (int dz = -1; dz <= 1; ++dz) {
              for (int dx = -1; dx <= 1; ++dx) {
                const int ax = cx + dx, ay = cy + dy, az = cz + dz;
                if (ax < 0 || ay < 0 || az < 0 || ax >= n.x() || ay >= n.y() || az >= n.z())
                  continue;
                const int j = cell(ax, ay, az);
                if (hull.cells[j] && label[j] < 0) {
                  label[j] = id;
                  queue.push_back(j);
                }
              }
            }
          }
        }
      }
    }
  }
  result.components = static_cast<int>(components.size());
  if (components.empty()) return result;
  // Per component: 0 dropped, 1 kept whole, 2 cut to reach_m.
  std::vector<int> keep(components.size(), 0);
  bool any = false;
  for (size_t k = 0; k < components.size(); ++k) {
    const Component& c = components[k];
    if (c.nearest > options_.touch_m) continue;
    any = true;
    keep[k] = c.beyond_reach > options_.shared_fraction * c.size ? 2 : 1;
  }
  if (!any) {
    const auto nearest = std::min_element(
        components.begin(), components.end(),
        [](const Component& a, const Component& b) { return a.nearest < b.nearest; });
    keep[nearest - components.begin()] = 1;
  }
  const double voxel = hull.grid.voxel;
  const int limit = static_cast<int>(std::ceil(options_.reach_m / voxel));
  std::vector<int> steps;  // to where the others were on the frame before
  if (options_.others_to_cover && others_before && !others_before->empty())
    steps = steps_to(hull, *others_before, limit);
  std::vector<Eigen::Vector3d> kept, dropped;
  for (size_t i = 0; i < hull.cells.size(); ++i) {
    if (!hull.cells[i]) continue;
    const int k = keep[label[i]];
    const int cx = static_cast<int>(i) % n.x(), cz = (static_cast<int>(i) / n.x()) % n.z(),
              cy = static_cast<int>(i) / (n.x() * n.z());
    const Eigen::Vector3d centre = hull.grid.center(hull.lo + Eigen::Vector3i(cx, cy, cz));
    // Everyone moves little from one frame to the next: a voxel nearer to where the others
    // were than to the person's body is theirs (what keeps a limb from following someone who
    // touches it), unless it lies on the body. Only what the components and the reach gave the
    // others is remembered: a voxel of the person's taken this way would otherwise stay theirs.
    const bool theirs = !steps.empty() && steps[i] <= limit &&
                        distance[i] > options_.own_margin_m && steps[i] * voxel < distance[i];
    if (k == 1 || (k == 2 && distance[i] <= options_.reach_m)) {
      if (!theirs) {
        kept.push_back(centre);
        continue;
      }
    } else if (options_.others_to_cover) {
      result.others.push_back(centre);
    }
    ++result.dropped_voxels;
    if (options_.others_to_cover) dropped.push_back(centre);
  }
  result.kept_voxels = static_cast<int>(kept.size());
  if (result.dropped_voxels == 0) return result;
  result.changed = true;
  const double half_diagonal = 0.5 * std::sqrt(3.0) * voxel;
  if (options_.others_to_cover && cover && cover->size() < silhouettes.size())
    cover->resize(silhouettes.size());
  for (size_t c = 0; c < cameras_.size() && c < silhouettes.size(); ++c) {
    const Camera& cam = cameras_[c];
    cv::Mat reach = cv::Mat::zeros(silhouettes[c].size(), CV_8UC1);
    cv::Mat near = cv::Mat::zeros(silhouettes[c].size(), CV_8UC1);
    paint_body(cam, body, options_.margin_m, near);
    paint_voxels(cam, kept, half_diagonal, reach);
    reach &= near;
    silhouettes[c] = silhouettes[c] & reach;
    if (cover && c < cover->size() && !(*cover)[c].empty()) (*cover)[c] = (*cover)[c] & reach;
    if (!options_.others_to_cover || !cover) continue;
    cv::Mat others = cv::Mat::zeros(silhouettes[c].size(), CV_8UC1);
    paint_voxels(cam, dropped, half_diagonal, others);
    cv::Mat own = cv::Mat::zeros(silhouettes[c].size(), CV_8UC1);
    paint_body(cam, body, options_.own_margin_m, own);
    // Where both the widened body and the others' volume project: theirs outside the body's
    // core, or where their volume lies well in front of it.
    constexpr float kFar = std::numeric_limits<float>::max();
    cv::Mat body_z(own.size(), CV_32F, cv::Scalar(kFar)), others_z = body_z.clone();
    body_depth(cam, body, options_.core_margin_m, voxel, body_z);
    voxel_depth(cam, dropped, half_diagonal, others_z);
    const cv::Mat hidden = (body_z == kFar) | (others_z < body_z - options_.front_m);
    cv::Mat moved = silhouettes[c] & others & (~own | hidden);
    if (distinct && c < distinct->size() && !(*distinct)[c].empty()) moved &= ~(*distinct)[c];
    result.covered_pixels += cv::countNonZero(moved);
    silhouettes[c] &= ~moved;
    cv::Mat& covered = (*cover)[c];
    covered = covered.empty() ? moved : covered | moved;
  }
  return result;
}

}  // namespace simcap::tracker
