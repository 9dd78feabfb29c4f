#include "tracker/moschini/pose_refiner.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "tracker/moschini/rim.h"

namespace simcap::tracker {
namespace {

// Centre of the occupied voxel nearest to `x` within `radius` voxels (Chebyshev shells), or
// empty; `x` itself when its voxel is occupied.
std::optional<Eigen::Vector3d> nearest_occupied(const Occupancy& hull, const Eigen::Vector3d& x,
                                                int radius) {
  const Eigen::Vector3i c = hull.grid.index(x);
  if (hull.occupied(c)) return x;
  for (int r = 1; r <= radius; ++r) {
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d found;
    for (int dy = -r; dy <= r; ++dy) {
      for (int dz = -r; dz <= r; ++dz) {
        // Inside the shell's y and z faces only its two x faces lie on it: stepping straight
        // from one to the other visits the shell in the cube's order without testing the rest.
        const int dx_step = std::abs(dy) == r || std::abs(dz) == r ? 1 : 2 * r;
        for (int dx = -r; dx <= r; dx += dx_step) {
          const Eigen::Vector3i v = c + Eigen::Vector3i(dx, dy, dz);
          if (!hull.occupied(v)) continue;
          const Eigen::Vector3d p = hull.grid.center(v);
          const double d = (p - x).squaredNorm();
          if (d < best) best = d, found = p;
        }
      }
    }
    if (best < std::numeric_limits<double>::infinity()) return found;
  }
  return std::nullopt;
}

// Where a ray passes its capsule: the ray's point nearest the axis, the signed miss of the
// surface there (negative inside) and the outward direction from the axis.
struct RayMiss {
  Eigen::Vector3d on_ray;
  double miss;
  Eigen::Vector3d outward;
};

inline bool miss_of(const SilhouetteRay& ray, const PlacedCapsule& capsule, RayMiss& m) {
  m.on_ray = nearest_on_ray(ray, capsule.a, capsule.a + capsule.ab);
  return capsule.distance(m.on_ray, &m.miss, &m.outward);
}

// The Jacobian of a point carried by one segment: only the torso's six parameters and the
// angles of the segment's chain (at most six) are non-zero, so it is kept in compact form.
struct PointJacobian {
  static constexpr int kMax = 15;
  std::array<int, kMax> index{};  // parameter of each column
  int n = 0;
  Eigen::Matrix<double, 3, kMax> J;  // only the first n columns are set and read
};

// Accumulates weighted residuals into the normal equations and the cost.
class Normal {
 public:
  using Chains = std::array<std::vector<int>, kSegmentCount>;
  Normal(const Chains& chains, const StickGeometry& g, const StickPose& pose, Eigen::MatrixXd* H,
         Eigen::VectorXd* rhs)
      : g_(g), pose_(pose), H_(H), rhs_(rhs), chains_(chains) {}

  // d(point)/d(parameters) for a point carried by `segment`: the root's translation, its
  // rotation as a left increment about t0, then the chain's angles.
  PointJacobian jacobian(int segment, const Eigen::Vector3d& p) const {
    PointJacobian j;
    for (int i = 0; i < 6; ++i) j.index[i] = i;
    j.J.leftCols<3>().setIdentity();
    const Eigen::Vector3d d = p - pose_.t0;
    j.J.block<3, 3>(0, 3) << 0, d.z(), -d.y(), -d.z(), 0, d.x(), d.y(), -d.x(), 0;
    j.n = 6;
    for (const int k : chains_[segment]) {
      j.index[j.n] = 6 + k;
      j.J.col(j.n) = g_.axis[k].cross(p - g_.pivot[k]);
      ++j.n;
    }
    return j;
  }
  // A vector residual r (data - model) whose model point has Jacobian j. (The products are
  // written out: for at most 15 columns, Eigen's general matrix product costs more.)
  void add(const PointJacobian& j, const Eigen::Vector3d& r, double w2) {
    cost_ += w2 * r.squaredNorm();
    ++count_;
    if (!H_) return;
    for (int a = 0; a < j.n; ++a) {
      const auto ja = j.J.col(a);
      (*rhs_)(j.index[a]) += w2 * ja.dot(r);
      for (int b = a; b < j.n; ++b) (*H_)(j.index[a], j.index[b]) += w2 * ja.dot(j.J.col(b));
    }
  }
  // A scalar residual e (minimized towards 0) whose gradient is n^T times the Jacobian j.
  void add_scalar(const PointJacobian& j, const Eigen::Vector3d& n, double e, double w2) {
    cost_ += w2 * e * e;
    ++count_;
    if (!H_) return;
    std::array<double, PointJacobian::kMax> g;
    for (int a = 0; a < j.n; ++a) g[a] = j.J.col(a).dot(n);
    for (int a = 0; a < j.n; ++a) {
      (*rhs_)(j.index[a]) -= w2 * e * g[a];
      for (int b = a; b < j.n; ++b) (*H_)(j.index[a], j.index[b]) += w2 * g[a] * g[b];
    }
  }
  // A scalar residual e on one parameter with slope `slope`.
  void add_parameter(int parameter, double slope, double e) {
    cost_ += e * e;
    ++count_;
    if (!H_) return;
    (*H_)(parameter, parameter) += slope * slope;
    (*rhs_)(parameter) -= slope * e;
  }
  // A one-sided residual that is satisfied: it counts, so that costs stay comparable.
  void add_zero(int n = 1) { count_ += n; }
  // `n` residuals of constant size e (no gradient): they count, so that costs stay comparable.
  void add_constant(int n, double e, double w2) {
    cost_ += n * w2 * e * e;
    count_ += n;
  }
  double cost() const { return count_ ? cost_ / count_ : 0.0; }
  int count() const { return count_; }
  // The residuals fill H's upper triangle only (a point's columns are in ascending parameter
  // order); this mirrors it.
  void symmetrize() {
    if (!H_) return;
    for (int b = 0; b < H_->cols(); ++b)
      for (int a = b + 1; a < H_->rows(); ++a) (*H_)(a, b) = (*H_)(b, a);
  }

 private:
  const StickGeometry& g_;
  const StickPose& pose_;
  Eigen::MatrixXd* H_;
  Eigen::VectorXd* rhs_;
  const Chains& chains_;
  double cost_ = 0;
  int count_ = 0;
};

// The rim residuals of one camera's view: points on each capsule's outline as that camera sees
// it, pulled towards the silhouette's edge when they project outside.
void add_rim(const SilhouetteView& view, const PlacedSurface& surface, const RefineOptions& options,
             double w2, Normal& normal) {
  for_each_rim_point(view, surface, options.rim_step_m, [&](const RimPoint& rim) {
    if (rim.outside) {
      normal.add(normal.jacobian(surface[rim.capsule].segment, rim.point), rim.target - rim.point,
                 w2);
    } else {
      normal.add_zero();
    }
  });
}

}  // namespace

PoseRefiner::PoseRefiner(const StickModel& model, const BodySurface& surface,
                         const RefineOptions& options)
    : model_(&model), surface_(surface), options_(options) {
  for (int s = 0; s < kSegmentCount; ++s) {
    chains_[s] = model.chain_angles(s);
    std::sort(chains_[s].begin(), chains_[s].end());
  }
}

// Which stick each residual belongs to, decided once per iteration (as ICP fixes its closest
// points before solving) so that a candidate step is judged on the same residuals.
struct PoseRefiner::Associations {
  std::vector<std::pair<int, int>> points;  // (point, segment), X84 inliers
  struct Sample {
    int segment;
    double along;  // on the joint line, 0 proximal, 1 distal
    Eigen::Vector3d target;
  };
  std::vector<Sample> contained;          // stick samples off the hull
  std::vector<std::pair<int, int>> rays;  // (ray, the capsule it passes most inside of)
  // How each of `rays` passes its capsule at `pose`, the pose associated at: the first
  // evaluation there reuses them.
  std::vector<RayMiss> misses;
  StickPose pose;
  // Rays passing deeper than RefineOptions::settled_depth_m inside a capsule: residual 0 here,
  // and counted as 0 for the steps this iteration tries.
  int settled_rays = 0;
  // Rays that no capsule their colour allows comes within RefineOptions::ray_max_miss_m of:
  // counted at that miss, so that a pose cannot lower its cost by leaving rays unexplained.
  int lost_rays = 0;
  std::vector<int> owner;  // per ray, the capsule it was given to (-1: none or not used)
};

namespace {

// The capsule `ray` passes most inside of (or nearest to) among the parts its colour may show,
// and how it passes it (`best`); -1 and a miss of inf when none may. The search stops at the
// first capsule the ray passes deeper than `settled_depth_m` inside; `hint`, when not -1, is
// tried first.
int nearest_capsule(const SilhouetteRay& ray, const PlacedSurface& surface, int hint,
                    double settled_depth_m, RayMiss& best_miss) {
  RayMiss m;
  int owner = -1;
  best_miss.miss = std::numeric_limits<double>::infinity();
  if (hint >= 0 && miss_of(ray, surface[hint], m)) owner = hint, best_miss = m;
  for (int c = 0; c < kCapsuleCount && best_miss.miss >= -settled_depth_m; ++c) {
    const PlacedCapsule& capsule = surface[c];
    if (c == hint || !(ray.parts >> capsule.segment & 1)) continue;
    // A sphere bounds its capsule's distance from below: skip the capsule when the ray passes
    // its sphere no nearer than the best miss so far (in squares; always when that is < -bound).
    const double reach = capsule.bound + best_miss.miss;
    if (reach <= 0 ||
        (capsule.centre - ray.origin).cross(ray.direction).squaredNorm() >= reach * reach) {
      continue;
    }
    if (miss_of(ray, capsule, m) && m.miss < best_miss.miss) owner = c, best_miss = m;
  }
  return owner;
}

// Normal equations whose step leaves every parameter but the arms' angles where it is.
void hold_all_but_arms(Eigen::MatrixXd& H, Eigen::VectorXd& rhs) {
  for (int i = 0; i < H.rows(); ++i) {
    const int angle = i - 6;
    if ((angle >= kLShoulder1 && angle <= kRElbow) ||
        (angle >= kLWristFlexion && angle <= kRWristDeviation))
      continue;
    H.row(i).setZero();
    H.col(i).setZero();
    H(i, i) = 1;
    rhs(i) = 0;
  }
}

}  // namespace

PoseRefiner::Associations PoseRefiner::associate(const IcpTargets& targets, const StickPose& pose,
                                                 const Associations* previous) const {
  const StickGeometry g = model_->geometry(pose);
  Associations a;
  a.pose = pose;
  // Centerline points: closest stick (Moschini's data-to-model matching), X84 inliers.
  std::vector<ClosestStick> closest(targets.points.size());
  std::vector<double> distances(targets.points.size());
  for (size_t i = 0; i < targets.points.size(); ++i) {
    closest[i] = closest_stick(g, targets.points[i]);
    distances[i] = closest[i].distance;
  }
  const double limit = x84_threshold(distances, options_.x84_k, options_.x84_floor_m);
  for (size_t i = 0; i < closest.size(); ++i) {
    if (closest[i].distance <= limit)
      a.points.emplace_back(static_cast<int>(i), closest[i].segment);
  }
  // Containment: stick samples off the hull and the nearest occupied voxel to each.
  if (targets.hull && targets.hull->count > 0 && options_.containment_weight > 0) {
    const Occupancy& hull = *targets.hull;
    for (int s = 0; s < kSegmentCount; ++s) {
      const Eigen::Vector3d ab = g.distal[s] - g.proximal[s];
      const int count = std::max(2, static_cast<int>(ab.norm() / (2 * hull.grid.voxel)));
      for (int i = 1; i <= count; ++i) {
        const double along = static_cast<double>(i) / count;
        const Eigen::Vector3d x = g.proximal[s] + along * ab;
        const auto inside = nearest_occupied(hull, x, options_.containment_search);
        if (inside && (*inside - x).norm() >= hull.grid.voxel) {
          a.contained.push_back({s, along, *inside});
        }
      }
    }
  }
  const PlacedSurface surface = place(surface_, g);
  // Silhouette rays: the capsule each passes nearest (most inside) among the parts its colour
  // may show. No X84 here: most rays meet a capsule, so the misses' median and MAD are zero and
  // it would reject every ray that still pulls a limb into place; misses beyond any limb's
  // reach count at that reach.
  if (!targets.rays.empty() && options_.ray_weight > 0) {
    a.owner.assign(targets.rays.size(), -1);
    const int every = options_.ray_every;
    const int used = (static_cast<int>(targets.rays.size()) + every - 1) / every;
    std::vector<RayMiss> misses(used);
    // Half of a frame's fitting, and each ray on its own: the pipeline's other thread, done
    // with the next frame's perception, takes a share (the result is the same in any order).
    tbb::parallel_for(tbb::blocked_range<int>(0, used, 256), [&](const tbb::blocked_range<int>& r) {
      for (int k = r.begin(); k < r.end(); ++k) {
        const size_t i = static_cast<size_t>(k) * every;
        // The capsule that held the ray at the last association holds it again, mostly: tried
        // first, it settles a ray still deep inside it at once and bounds the others tightly.
        a.owner[i] = nearest_capsule(targets.rays[i], surface, previous ? previous->owner[i] : -1,
                                     options_.settled_depth_m, misses[k]);
      }
    });
    for (int k = 0; k < used; ++k) {
      const size_t i = static_cast<size_t>(k) * every;
      const int owner = a.owner[i];
      const RayMiss& m = misses[k];
      if (owner < 0 || m.miss > options_.ray_max_miss_m) {
        ++a.lost_rays;
      } else if (m.miss < -options_.settled_depth_m) {
        ++a.settled_rays;
      } else {
        a.rays.emplace_back(static_cast<int>(i), owner);
        a.misses.push_back(m);
      }
    }
  }
  return a;
}

std::vector<int> PoseRefiner::missed_rays(const IcpTargets& targets, const StickPose& pose,
                                          double min_miss_m, int every) const {
  std::vector<int> missed;
  const PlacedSurface surface = place(surface_, model_->geometry(pose));
  for (size_t i = 0; i < targets.rays.size(); i += every) {
    // Stopped at the first capsule the ray passes within min_miss_m of: most rays, at once.
    RayMiss m;
    nearest_capsule(targets.rays[i], surface, -1, -min_miss_m, m);
    if (m.miss > min_miss_m) {
      missed.push_back(static_cast<int>(i));
    }
  }
  return missed;
}

double PoseRefiner::evaluate(const IcpTargets& targets, const Associations& a,
                             const StickPose& pose, const StickPose* start, Eigen::MatrixXd* H,
                             Eigen::VectorXd* rhs, int* count) const {
  const StickGeometry g = model_->geometry(pose);
  Normal normal(chains_, g, pose, H, rhs);
  // Centerline points: only the distance across a stick's line counts, except past a free tip.
  const double wp2 = options_.centerline_weight * options_.centerline_weight;
  for (const auto& [i, s] : a.points) {
    const Eigen::Vector3d& x = targets.points[i];
    const Eigen::Vector3d ab = g.line_distal[s] - g.line_proximal[s];
    const double raw = (x - g.line_proximal[s]).dot(ab) / ab.squaredNorm();
    const bool free_tip = raw > 1 && (s == kHead || s == kLForearm || s == kRForearm);
    const Eigen::Vector3d match = g.line_proximal[s] + (free_tip ? 1.0 : raw) * ab;
    PointJacobian j = normal.jacobian(s, match);
    Eigen::Vector3d r = x - match;
    if (!free_tip) {
      const Eigen::Vector3d u = ab.normalized();
      const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - u * u.transpose();
      j.J.leftCols(j.n) = (P * j.J.leftCols(j.n)).eval();
      r = P * r;
    }
    normal.add(j, r, wp2);
  }
  const double wc2 = options_.containment_weight * options_.containment_weight;
  for (const auto& c : a.contained) {
    const Eigen::Vector3d x =
        g.proximal[c.segment] + c.along * (g.distal[c.segment] - g.proximal[c.segment]);
    normal.add(normal.jacobian(c.segment, x), c.target - x, wc2);
  }
  const PlacedSurface surface = place(surface_, g);
  const double wr2 = options_.ray_weight * options_.ray_weight;
  normal.add_zero(a.settled_rays);
  normal.add_constant(a.lost_rays, options_.ray_max_miss_m, wr2);
  const bool associated_here =
      pose.t0 == a.pose.t0 && pose.R0 == a.pose.R0 && pose.theta == a.pose.theta;
  for (size_t k = 0; k < a.rays.size(); ++k) {
    const auto [i, c] = a.rays[k];
    RayMiss computed;
    const RayMiss& m = associated_here ? a.misses[k] : computed;
    if ((!associated_here && !miss_of(targets.rays[i], surface[c], computed)) || m.miss <= 0) {
      normal.add_zero();
      continue;
    }
    normal.add_scalar(normal.jacobian(surface[c].segment, m.on_ray - m.miss * m.outward),
                      -m.outward, m.miss, wr2);
  }
  if (targets.views && options_.rim_weight > 0) {
    const double w2 = options_.rim_weight * options_.rim_weight;
    for (const SilhouetteView& view : *targets.views) {
      if (!view.empty()) add_rim(view, surface, options_, w2, normal);
    }
  }
  auto prior = [&](std::initializer_list<int> angles, double slope) {
    if (slope <= 0) return;
    for (const int k : angles) {
      if (k < model_->angle_count()) normal.add_parameter(6 + k, slope, slope * pose.theta[k]);
    }
  };
  prior({kLHip1, kRHip1, kLHipTwist, kRHipTwist}, options_.leg_prior_m_per_rad);
  if (start && options_.motion_prior_m_per_rad > 0) {
    const double slope = options_.motion_prior_m_per_rad;
    for (int k = 0; k < model_->angle_count(); ++k) {
      normal.add_parameter(6 + k, slope, slope * (pose.theta[k] - start->theta[k]));
    }
    const Eigen::AngleAxisd turn(pose.R0 * start->R0.transpose());
    const Eigen::Vector3d rot = turn.angle() * turn.axis();
    for (int i = 0; i < 3; ++i) {
      normal.add_parameter(i, slope, slope * (pose.t0(i) - start->t0(i)));
      normal.add_parameter(3 + i, slope, slope * rot(i));
    }
  }
  normal.symmetrize();
  if (count) *count = normal.count();
  return normal.cost();
}

double PoseRefiner::cost(const IcpTargets& targets, const StickPose& pose) const {
  return evaluate(targets, associate(targets, pose, nullptr), pose, targets.prediction, nullptr,
                  nullptr);
}

Eigen::VectorXd PoseRefiner::gradient(const IcpTargets& targets, const StickPose& pose) const {
  const int np = 6 + model_->angle_count();
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(np, np);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(np);
  int count = 0;
  evaluate(targets, associate(targets, pose, nullptr), pose, targets.prediction, &H, &rhs, &count);
  // rhs is Jᵀ W r for residuals r = data − model, and the cost Σ w² r² / count.
  return count > 0 ? Eigen::VectorXd(-2.0 * rhs / count)
                   : Eigen::VectorXd(Eigen::VectorXd::Zero(np));
}

void PoseRefiner::refine(const IcpTargets& targets, StickPose& pose) const {
  const int na = model_->angle_count();
  const int np = 6 + na;
  const auto& ranges = model_->ranges();
  // Levenberg-Marquardt: the damping shrinks after a step that lowers the cost and grows (the
  // step is retried, up to 10 times: one-sided ray residuals make the first Gauss-Newton model
  // optimistic far from the data) after one that does not.
  double lambda = options_.damping;
  const StickPose start = targets.prediction ? *targets.prediction : pose;
  Associations assoc;
  for (int it = 0; it < options_.iterations; ++it) {
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(np, np);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(np);
    assoc = associate(targets, pose, it > 0 ? &assoc : nullptr);
    const double cost = evaluate(targets, assoc, pose, &start, &H, &rhs);
    if (options_.arms_only) hold_all_but_arms(H, rhs);
    const double scale = H.diagonal().mean();
    if (!(scale > 0)) return;
    bool improved = false;
    for (int attempt = 0; attempt < 10 && !improved; ++attempt) {
      Eigen::MatrixXd A = H;
      A.diagonal().array() += lambda * scale;
      const Eigen::VectorXd step = A.ldlt().solve(rhs);
      if (!step.allFinite()) return;
      StickPose next = pose;
      next.t0 += step.head<3>();
      const Eigen::Vector3d rot = step.segment<3>(3);
      if (rot.norm() > 0) next.R0 = Eigen::AngleAxisd(rot.norm(), rot.normalized()) * next.R0;
      for (int k = 0; k < na; ++k) {
        next.theta[k] = limit_angle(next.theta[k] + step(6 + k), ranges[k]);
      }
      const double next_cost = evaluate(targets, assoc, next, &start, nullptr, nullptr);
      if (next_cost < cost) {
        pose = next;
        lambda = std::max(lambda / 3, 1e-6);
        improved = true;
        if (cost - next_cost < options_.tolerance * cost) return;
      } else {
        lambda *= 4;
      }
    }
    if (!improved) return;
  }
}

}  // namespace simcap::tracker
