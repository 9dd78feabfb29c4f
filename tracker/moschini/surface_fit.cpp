#include "tracker/moschini/surface_fit.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>

#include "tracker/moschini/rim.h"

namespace simcap::tracker {
namespace {

// The head, then one group per left/right pair of capsules.
constexpr int kGroups = (kCapsuleCount + 1) / 2;
// Per group: radius at a, radius at b, a's offset along e1 and e2, b's offset along e1 and e2.
constexpr int kPerGroup = 6;
constexpr int kParameters = kGroups * kPerGroup;
using Vector = Eigen::Matrix<double, kParameters, 1>;
using Matrix = Eigen::Matrix<double, kParameters, kParameters>;

int group_of(int capsule) {
  return (capsule + 1) / 2;
}
// Right capsules (even, after the head) are mirrored across the body's midline.
bool is_mirrored(int capsule) {
  return capsule > 0 && capsule % 2 == 0;
}
Eigen::Vector3d mirror(const Eigen::Vector3d& v, bool m) {
  return m ? Eigen::Vector3d(-v.x(), v.y(), v.z()) : v;
}

// Two directions across a capsule's axis in its segment's frame, for its unmirrored shape: the
// frame's X (left) where it is not along the axis, and the direction across both.
std::array<Eigen::Vector3d, 2> across(const CapsuleShape& shape) {
  const Eigen::Vector3d u = (shape.b - shape.a).normalized();
  Eigen::Vector3d e1 = Eigen::Vector3d::UnitX() - u.x() * u;
  if (e1.norm() < 0.3) e1 = Eigen::Vector3d::UnitZ() - u.z() * u;
  e1.normalize();
  return {e1, u.cross(e1)};
}

class SurfaceProblem {
 public:
  SurfaceProblem(const StickModel& model, const StickPose& pose, const BodySurface& start,
                 const std::vector<SilhouetteRay>& rays, const std::vector<SilhouetteView>& views,
                 const SurfaceFitOptions& options)
      : g_(model.geometry(pose)), start_(start), rays_(rays), views_(views), options_(options) {
    for (int c = 0; c < kCapsuleCount; ++c) {
      const int group = group_of(c);
      if (!is_mirrored(c)) {
        base_[group] = start[c];
        axes_[group] = across(start[c]);
        p0_.segment<kPerGroup>(kPerGroup * group) << start[c].ra, start[c].rb, 0, 0, 0, 0;
      }
    }
  }
  const Vector& start_parameters() const { return p0_; }

  BodySurface surface(const Vector& p) const {
    BodySurface s = start_;
    for (int c = 0; c < kCapsuleCount; ++c) {
      const int group = group_of(c);
      const auto q = p.segment<kPerGroup>(kPerGroup * group);
      const auto& [e1, e2] = axes_[group];
      const bool m = is_mirrored(c);
      s[c].ra = q(0);
      s[c].rb = q(1);
      s[c].a = mirror(base_[group].a + q(2) * e1 + q(3) * e2, m);
      s[c].b = mirror(base_[group].b + q(4) * e1 + q(5) * e2, m);
    }
    return s;
  }

  // The cost at p with rays judged by a soft minimum of this softness (metres), and with H and
  // rhs the Gauss-Newton normal equations.
  double evaluate(const Vector& p, double softness, Matrix* H, Vector* rhs) const {
    const BodySurface shape = surface(p);
    const PlacedSurface placed = place(shape, g_);
    double cost = 0;
    if (H) H->setZero(), rhs->setZero();
    // d(world point)/d(parameters of its capsule's group) for a point at axis parameter t, and
    // the direction `radial` in which the radius moves it.
    auto point_jacobian = [&](int c, double t, const Eigen::Vector3d& radial) {
      Eigen::Matrix<double, 3, kPerGroup> J;
      const Eigen::Matrix3d& R = g_.rotation[shape[c].segment];
      const auto& [e1, e2] = axes_[group_of(c)];
      const bool m = is_mirrored(c);
      J.col(0) = (1 - t) * radial;
      J.col(1) = t * radial;
      J.col(2) = (1 - t) * (R * mirror(e1, m));
      J.col(3) = (1 - t) * (R * mirror(e2, m));
      J.col(4) = t * (R * mirror(e1, m));
      J.col(5) = t * (R * mirror(e2, m));
      return J;
    };
    auto add = [&](int c, const Eigen::Matrix<double, 3, kPerGroup>& J, const Eigen::Vector3d& r) {
      cost += r.squaredNorm();
      if (!H) return;
      const int o = kPerGroup * group_of(c);
      H->block<kPerGroup, kPerGroup>(o, o) += J.transpose() * J;
      rhs->segment<kPerGroup>(o) += J.transpose() * r;
    };
    // Rays: each must pass inside a capsule. Its residual is how far it misses them, a soft
    // minimum over the capsules at `softness` (a hard one at 0): a ray the arm in front of the
    // chest misses pulls the chest too, where the arm cannot grow to meet it.
    std::array<double, kCapsuleCount> miss;
    std::array<Eigen::Matrix<double, 1, kPerGroup>, kCapsuleCount> slope;
    for (const SilhouetteRay& ray : rays_) {
      double best = std::numeric_limits<double>::infinity();
      for (int c = 0; c < kCapsuleCount; ++c) {
        const PlacedCapsule& capsule = placed[c];
        const Eigen::Vector3d q = nearest_on_ray(ray, capsule.a, capsule.a + capsule.ab);
        // On the axis the outward direction is undefined and the miss has no slope.
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        if (!capsule.distance(q, &miss[c], &n)) miss[c] = -capsule.radius(capsule.along(q));
        // The surface point nearest the ray moves with the capsule; only its normal part counts.
        slope[c] = n.transpose() * point_jacobian(c, capsule.along(q), n);
        best = std::min(best, miss[c]);
      }
      double e = best;
      std::array<double, kCapsuleCount> weight{};
      weight.fill(0);
      if (softness > 0) {
        double sum = 0;
        for (int c = 0; c < kCapsuleCount; ++c)
          sum += weight[c] = std::exp((best - miss[c]) / softness);
        e = best - softness * std::log(sum);
        for (double& w : weight) w /= sum;
      } else {
        for (int c = 0; c < kCapsuleCount; ++c) weight[c] = miss[c] == best;
      }
      if (e <= 0) continue;
      if (e > options_.ray_max_miss_m) {
        cost += options_.ray_max_miss_m * options_.ray_max_miss_m;
        continue;
      }
      cost += e * e;
      if (!H) continue;
      Vector j = Vector::Zero();
      for (int c = 0; c < kCapsuleCount; ++c) {
        if (weight[c] > 1e-4) j.segment<kPerGroup>(kPerGroup * group_of(c)) += weight[c] * slope[c];
      }
      *H += j * j.transpose();
      *rhs += j * e;
    }
    // Outlines: every capsule's, as each camera sees it, inside that camera's silhouette.
    for (const SilhouetteView& view : views_) {
      if (view.empty()) continue;
      for_each_rim_point(view, placed, options_.rim_step_m, [&](const RimPoint& rim) {
        if (rim.outside) {
          add(rim.capsule, point_jacobian(rim.capsule, rim.t, rim.radial), rim.target - rim.point);
        }
      });
    }
    // The typical surface, for what the views leave open.
    for (int k = 0; k < kParameters; ++k) {
      const double sigma = k % kPerGroup < 2 ? options_.radius_prior_m : options_.offset_prior_m;
      const double w = kPriorWeight / sigma;
      const double r = w * (p(k) - p0_(k));
      cost += r * r;
      if (H) {
        (*H)(k, k) += w * w;
        (*rhs)(k) -= w * r;
      }
    }
    return cost;
  }

 private:
  // A prior residual of one sigma costs as much as a ray missing by a centimetre: the views
  // decide wherever they see a capsule's edge.
  static constexpr double kPriorWeight = 0.01;
  StickGeometry g_;
  BodySurface start_;
  std::array<CapsuleShape, kGroups> base_;
  std::array<std::array<Eigen::Vector3d, 2>, kGroups> axes_;
  Vector p0_;
  const std::vector<SilhouetteRay>& rays_;
  const std::vector<SilhouetteView>& views_;
  SurfaceFitOptions options_;
};

}  // namespace

BodySurface fit_surface(const StickModel& model, const StickPose& pose, const BodySurface& start,
                        const std::vector<SilhouetteRay>& rays,
                        const std::vector<SilhouetteView>& views,
                        const SurfaceFitOptions& options) {
  const SurfaceProblem problem(model, pose, start, rays, views, options);
  Vector p = problem.start_parameters();
  double lambda = 1e-3;
  // Continuation: the rays' soft minimum halves every iteration, from a few centimetres (where
  // every capsule near a ray shares its pull) to a hard minimum (where only the nearest does).
  double softness = options.initial_softness_m;
  Matrix H;
  Vector rhs;
  for (int it = 0; it < options.iterations; ++it) {
    const double cost = problem.evaluate(p, softness, &H, &rhs);
    bool improved = false;
    for (int attempt = 0; attempt < 10 && !improved; ++attempt) {
      Matrix A = H;
      A.diagonal().array() += lambda * H.diagonal().mean();
      Vector next = p + A.ldlt().solve(rhs);
      for (int g = 0; g < kGroups; ++g) {
        for (int r = 0; r < 2; ++r) {
          double& radius = next(kPerGroup * g + r);
          radius = std::max(radius, options.min_radius_m);
        }
      }
      if (problem.evaluate(next, softness, nullptr, nullptr) < cost) {
        p = next;
        lambda = std::max(lambda / 3, 1e-7);
        improved = true;
      } else {
        lambda *= 4;
      }
    }
    if (!improved && softness == 0) break;
    softness = softness > 0.001 ? 0.5 * softness : 0.0;
  }
  return problem.surface(p);
}

}  // namespace simcap::tracker
