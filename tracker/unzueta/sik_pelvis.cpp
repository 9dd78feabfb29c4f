#include "tracker/unzueta/sik_pelvis.h"

#include <algorithm>

namespace simcap {
namespace {

// v projected onto the plane normal to unit y and normalised; zero when v is (nearly) along y.
Eigen::Vector3d in_plane(const Eigen::Vector3d& v, const Eigen::Vector3d& y) {
  const Eigen::Vector3d p = v - v.dot(y) * y;
  const double n = p.norm();
  return n > 1e-9 ? Eigen::Vector3d(p / n) : Eigen::Vector3d::Zero();
}

}  // namespace

Eigen::Vector3d SikPelvisEstimator::travel(const Eigen::Vector3d& pelvis,
                                           const Eigen::Vector3d& y) {
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  // The newest past position a stride away; older ones are no longer needed.
  for (auto it = trail_.rbegin(); it != trail_.rend(); ++it) {
    const Eigen::Vector3d d = pelvis - *it;
    if ((d - d.dot(y) * y).norm() >= kTravelDistance) {
      direction = in_plane(d, y);
      trail_.erase(trail_.begin(), std::prev(it.base()));
      break;
    }
  }
  trail_.push_back(pelvis);
  if (trail_.size() > kTrailFrames) trail_.pop_front();
  return direction;
}

Eigen::Matrix3d SikPelvisEstimator::estimate(const SikTargets& t) {
  const Eigen::Vector3d up = t.head - t.pelvis;
  if (up.norm() < 1e-9) return previous_;
  const Eigen::Vector3d y = up.normalized();
  Eigen::Vector3d x = weights_.wrists * in_plane(t.wrist[kLeft] - t.wrist[kRight], y) +
                      weights_.ankles * in_plane(t.ankle[kLeft] - t.ankle[kRight], y);
  if (weights_.travel > 0.0) {
    // Facing the travel direction makes X = Y x travel (Z = X x Y forward).
    const Eigen::Vector3d facing = in_plane(y.cross(travel(t.pelvis, y)), y);
    x += weights_.travel * std::max(0.0, facing.dot(in_plane(x, y))) * facing;
  }
  if (has_previous_) x += weights_.previous * in_plane(previous_.col(0), y);
  x = in_plane(x, y);
  if (x.isZero()) {
    x = in_plane(previous_.col(0), y);
    if (x.isZero()) x = in_plane(previous_.col(2).cross(y), y);
  }
  Eigen::Matrix3d frame;
  frame.col(0) = x;
  frame.col(1) = y;
  frame.col(2) = x.cross(y);
  previous_ = frame;
  has_previous_ = true;
  return frame;
}

}  // namespace simcap
