#include "tracker/moschini/articulated_icp.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "tracker/moschini/weop.h"

namespace simcap::tracker {
namespace {

void match_all(const StickGeometry& g, const std::vector<Eigen::Vector3d>& points,
               std::vector<ClosestStick>& closest, std::vector<double>& distances) {
  closest.resize(points.size());
  distances.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    closest[i] = closest_stick(g, points[i]);
    distances[i] = closest[i].distance;
  }
}

}  // namespace

ArticulatedIcp::ArticulatedIcp(const StickModel& model, const BodySurface& surface,
                               const IcpOptions& options)
    : model_(&model), options_(options), refiner_(model, surface, options.refine) {}

int ArticulatedIcp::fit_segment(int segment, const std::vector<Eigen::Vector3d>& points,
                                StickPose& pose, std::vector<ClosestStick>& closest,
                                std::vector<double>& distances) const {
  const int n = static_cast<int>(points.size());
  const int capacity = n + 2;
  Eigen::Matrix3Xd A(3, capacity), B(3, capacity);
  Eigen::VectorXd w(capacity);
  std::vector<char> spin_info(capacity);
  double previous = std::numeric_limits<double>::infinity();
  int iterations = 0;
  for (; iterations < options_.max_iterations; ++iterations) {
    const StickGeometry g = model_->geometry(pose);
    match_all(g, points, closest, distances);
    const double limit = x84_threshold(distances, options_.x84_k, options_.x84_floor_m);
    // Alg. 2 step 4-5: weight 1 on this stick, ε on descendants, 0 elsewhere and for outliers.
    int m = 0;
    double weighted = 0, weight_sum = 0;
    for (int i = 0; i < n; ++i) {
      const ClosestStick& c = closest[i];
      if (c.distance > limit) continue;
      double wi = 0;
      if (model_->moving_segment(c.segment) == segment) {
        wi = 1.0;
      } else if (is_strict_descendant(c.segment, segment)) {
        wi = options_.descendant_weight;
      }
      if (wi == 0) continue;
      A.col(m) = c.match;
      B.col(m) = points[i];
      w(m) = wi;
      spin_info[m] = c.segment != segment;
      weighted += wi * wi * c.distance;
      weight_sum += wi * wi;
      ++m;
    }
    if (weight_sum == 0) break;
    const double mean = weighted / weight_sum;
    if (mean < options_.converged_m || previous - mean < options_.min_improvement_m) break;
    previous = mean;
    // Two anchors off the stick's axis, a quarter of its length out along its frame's X and Z
    // from its far end, mapped onto themselves.
    const double reach = 0.25 * model_->length(segment);
    for (int axis : {0, 2}) {
      const Eigen::Vector3d anchor = g.line_distal[segment] + g.rotation[segment].col(axis) * reach;
      A.col(m) = anchor;
      B.col(m) = anchor;
      w(m) = options_.anchor_weight;
      spin_info[m] = 1;
      ++m;
    }
    const auto a = A.leftCols(m);
    const auto b = B.leftCols(m);
    const auto ww = w.head(m);
    if (segment == kPelvis) {
      const RigidMotion motion = weop(a, b, ww);
      pose.R0 = motion.R * pose.R0;
      pose.t0 = motion.R * pose.t0 + motion.t;
    } else {
      const Eigen::Vector3d pivot = g.proximal[segment];
      const Eigen::Matrix3Xd a0 = a.colwise() - pivot;
      const Eigen::Matrix3Xd b0 = b.colwise() - pivot;
      // WOPP sets where the stick points. Its spin about the stick is then solved alone, from
      // the descendants' points and the anchors, within what the joint's twist range allows:
      // the stick's own points are collinear, and when they run a few cm off the stick (a
      // hull's centroids do) an unconstrained SVD would rather spin the limb half a turn.
      const Eigen::Vector3d axis = g.rotation[segment] * model_->direction(segment);
      const Eigen::Matrix3d swing =
          Eigen::Quaterniond::FromTwoVectors(axis, wopp(a0, b0, ww) * axis).toRotationMatrix();
      double spin = 0;
      const int twist = model_->twist_angle(segment);
      if (twist >= 0) {
        const Eigen::Vector3d k = swing * axis;
        double c = 0, s = 0;  // the spin φ maximizes c cos φ + s sin φ
        for (int i = 0; i < m; ++i) {
          if (!spin_info[i]) continue;  // own points carry no spin information
          const Eigen::Vector3d q = swing * a0.col(i);
          const double w2 = w(i) * w(i);
          c += w2 * b0.col(i).dot(q - q.dot(k) * k);
          s += w2 * b0.col(i).dot(k.cross(q));
        }
        // Spinning by φ about the stick's world direction changes the twist angle by -φ for a
        // stick along its frame's -Y (a limb), by φ along +Y (the chest).
        const AngleRange& range = model_->ranges()[twist];
        const bool down = model_->direction(segment).y() < 0;
        const double lo = down ? pose.theta[twist] - range.hi : range.lo - pose.theta[twist];
        const double hi = down ? pose.theta[twist] - range.lo : range.hi - pose.theta[twist];
        spin = std::clamp(std::atan2(s, c), lo, hi);
        const double other = spin == lo ? hi : lo;
        if (c * std::cos(other) + s * std::sin(other) > c * std::cos(spin) + s * std::sin(spin)) {
          spin = other;
        }
      }
      const Eigen::Matrix3d turn = Eigen::AngleAxisd(spin, swing * axis).toRotationMatrix() * swing;
      model_->set_segment_rotation(pose, segment, turn * g.rotation[segment]);
    }
  }
  return iterations;
}

IcpResult ArticulatedIcp::fit(const IcpTargets& targets, StickPose& pose) const {
  const std::vector<Eigen::Vector3d>& points = targets.points;
  IcpResult result;
  if (points.empty()) return result;
  std::vector<ClosestStick> closest;
  std::vector<double> distances;
  for (int sweep = 0; sweep < options_.sweeps; ++sweep) {
    for (int s = 0; s < kSegmentCount; ++s) {
      // A segment without angles moves with its parent, whose fit counts its points fully.
      if (model_->moving_segment(s) != s) continue;
      result.iterations += fit_segment(s, points, pose, closest, distances);
    }
  }
  refiner_.refine(targets, pose);
  const IcpResult final_fit = evaluate(points, pose);
  result.mean_distance_m = final_fit.mean_distance_m;
  result.inlier_fraction = final_fit.inlier_fraction;
  return result;
}

IcpResult ArticulatedIcp::evaluate(const std::vector<Eigen::Vector3d>& points,
                                   const StickPose& pose) const {
  IcpResult result;
  if (points.empty()) return result;
  std::vector<ClosestStick> closest;
  std::vector<double> distances;
  match_all(model_->geometry(pose), points, closest, distances);
  const double limit = x84_threshold(distances, options_.x84_k, options_.x84_floor_m);
  double sum = 0;
  int inliers = 0;
  for (const double d : distances) {
    if (d > limit) continue;
    sum += d;
    ++inliers;
  }
  result.mean_distance_m = inliers ? sum / inliers : 0.0;
  result.inlier_fraction = static_cast<double>(inliers) / static_cast<double>(points.size());
  return result;
}

}  // namespace simcap::tracker
