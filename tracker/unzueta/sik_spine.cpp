#include "tracker/unzueta/sik_spine.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace simcap {
namespace {

// Alg. 9's step angles: coarse until the length overshoots, then fine back until it overshoots
// the other way.
constexpr double kCoarseStep = 0.1, kFineStep = 0.01;
// Bend bound when limits are off: the root turned a right angle makes the spine a half circle.
constexpr double kMaxBend = std::numbers::pi / 2;
// Precomputed stretching postures (thesis: "a set of precomputed stretching postures"; their
// number is simcap's choice): 5% steps from neutral to straight, the first one at least as long
// as the target wins.
constexpr int kStretchPostures = 21;

}  // namespace

SikSpine::SikSpine(const SikBody& body, const SikLimits& limits, SikSpineBend bend)
    : body_(body), limits_(limits), bend_(bend), chain_(body.spine()) {
  const int m = static_cast<int>(chain_.size()) - 1;
  if (m < 1) throw Error("SIK: the spine needs a joint between humanoid_root and skullbase");
  shape_.assign(chain_.size(), Eigen::Quaterniond::Identity());
  const Eigen::Vector3d neutral = head_offset(shape_);
  neutral_length_ = neutral.norm();
  current_length_ = neutral_length_;

  // The bend is spread so that each non-root joint turns 2 phi_root / m (eq. 8); its flexion
  // limit (the cone at theta = 0) bounds phi_root.
  min_phi_root_ = -kMaxBend;
  for (int i = 1; i <= m; ++i) {
    if (limits_[chain_[i]].kind != SikLimitKind::ball) continue;
    min_phi_root_ = std::max(min_phi_root_, -0.5 * m * limits_.max_swing(chain_[i], 0.0));
  }

  // Full stretch: every segment turned onto the neutral root-head line.
  const Eigen::Vector3d line = neutral.normalized();
  std::vector<Eigen::Quaterniond> full(chain_.size());
  Eigen::Quaterniond parent_world = Eigen::Quaterniond::Identity();
  for (size_t i = 0; i < chain_.size(); ++i) {
    const Eigen::Vector3d& seg = body_.segment_direction(chain_[i]);
    const Eigen::Quaterniond world =
        seg.isZero() ? parent_world : Eigen::Quaterniond::FromTwoVectors(seg, line);
    full[i] = i == 0 ? world : parent_world.conjugate() * world;
    parent_world = world;
  }
  for (int k = 0; k < kStretchPostures; ++k) {
    const double s = static_cast<double>(k) / (kStretchPostures - 1);
    std::vector<Eigen::Quaterniond> posture(chain_.size());
    for (size_t i = 0; i < chain_.size(); ++i) {
      posture[i] = Eigen::Quaterniond::Identity().slerp(s, full[i]);
    }
    stretch_length_.push_back(head_offset(posture).norm());
    stretch_.push_back(std::move(posture));
  }
}

void SikSpine::reset() {
  phi_root_ = 0.0;
  stretch_index_ = 0;
  current_length_ = neutral_length_;
}

Eigen::Vector3d SikSpine::head_offset(const std::vector<Eigen::Quaterniond>& rotations) const {
  Eigen::Quaterniond world = rotations[0];
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (size_t i = 1; i < chain_.size(); ++i) {
    p += world * body_.offset(chain_[i]);
    world = world * rotations[i];
  }
  return p + world * body_.offset(body_.head());
}

Eigen::Vector3d SikSpine::bent(double phi_root, std::vector<Eigen::Quaterniond>& rotations) const {
  // The thesis leaves the bending plane's orientation implicit; simcap bends in the pelvis'
  // sagittal plane (about its X axis) with phi_root <= 0: the pelvis tilts back against the
  // root-head line and the vertebrae curl forward, i.e. trunk flexion.
  const int m = static_cast<int>(chain_.size()) - 1;
  rotations[0] = Eigen::AngleAxisd(phi_root, Eigen::Vector3d::UnitX());
  const Eigen::Quaterniond rest(Eigen::AngleAxisd(-2.0 * phi_root / m, Eigen::Vector3d::UnitX()));
  for (int i = 1; i <= m; ++i) rotations[i] = rest;
  return head_offset(rotations);
}

double SikSpine::search_bend(double target_length) {
  double phi = phi_root_;
  auto length = [&] { return bent(phi, shape_).norm(); };
  // One step of Alg. 9, kept inside [min_phi_root_, 0]; false when the bound stops it.
  auto step = [&](double delta) {
    const double next = std::clamp(phi + delta, min_phi_root_, 0.0);
    const bool moved = next != phi;
    phi = next;
    return moved;
  };
  double l = length();
  const double sign = l > target_length ? 1.0 : -1.0;
  while (sign * l > sign * target_length && step(-sign * kCoarseStep)) l = length();
  while (sign * l < sign * target_length && step(sign * kFineStep)) l = length();
  return phi;
}

double SikSpine::flexion_share(const Eigen::Matrix3d& pelvis_frame) const {
  if (bend_ == SikSpineBend::thesis) return 1.0;
  // The pelvis' front (Z, normal to the pelvis-head line Y) dips by the sine of the line's
  // forward lean; past the horizontal (Y pointing down) the sine falls again, the flexion not.
  const double dip = -pelvis_frame(1, 2);
  if (dip > 0.0 && pelvis_frame(1, 1) < 0.0) return 1.0;
  return std::clamp(dip, 0.0, 1.0);
}

void SikSpine::solve(const SikTargets& targets, const Eigen::Matrix3d& pelvis_frame, bool limits,
                     Pose& pose) {
  Eigen::Vector3d line = targets.head - targets.pelvis;
  const double target_length = line.norm();
  line = target_length > 1e-9 ? Eigen::Vector3d(line / target_length)
                              : Eigen::Vector3d(pelvis_frame.col(1));

  if (target_length < neutral_length_) {
    if (current_length_ > neutral_length_) reset();  // Alg. 8 line 6: leave the stretch
    stretch_index_ = 0;
    phi_root_ = search_bend(target_length);
    bent(flexion_share(pelvis_frame) * phi_root_, shape_);
  } else {
    phi_root_ = 0.0;
    const auto it = std::lower_bound(stretch_length_.begin(), stretch_length_.end(), target_length);
    stretch_index_ = std::min(static_cast<int>(it - stretch_length_.begin()), kStretchPostures - 1);
    shape_ = stretch_[stretch_index_];
  }
  if (limits) {
    for (size_t i = 1; i < chain_.size(); ++i) shape_[i] = limits_.clamp(chain_[i], shape_[i]);
  }
  const Eigen::Vector3d head = head_offset(shape_);
  current_length_ = head.norm();

  // Alg. 8 lines 14-16 in one step: turn the bent spine so that its root-head vector lies on the
  // target line, then about that line so that the pelvis' X axis meets the estimated one.
  const Eigen::Quaterniond onto_line = Eigen::Quaterniond::FromTwoVectors(head, line);
  Eigen::Vector3d x = onto_line * (shape_[0] * Eigen::Vector3d::UnitX());
  x -= x.dot(line) * line;
  const Eigen::Vector3d wanted = pelvis_frame.col(0);
  const double spin = std::atan2(x.cross(wanted).dot(line), x.dot(wanted));
  pose.rotations[chain_[0]] = (Eigen::AngleAxisd(spin, line) * onto_line * shape_[0]).normalized();
  for (size_t i = 1; i < chain_.size(); ++i) pose.rotations[chain_[i]] = shape_[i];
  // Alg. 8 line 17: half of the length error at each end.
  pose.root_position = targets.pelvis - 0.5 * (current_length_ - target_length) * line;
}

void SikSpine::twist_to_head(const Eigen::Quaterniond& head, bool limits, Pose& pose) const {
  constexpr double kTwistError = 0.01;  // radians
  constexpr int kMaxSweeps = 20;
  const int n = static_cast<int>(chain_.size());
  std::vector<Eigen::Quaterniond> world(n);
  std::vector<Eigen::Vector3d> at(n);
  Eigen::Vector3d head_at;
  auto forward = [&] {
    world[0] = pose.rotations[chain_[0]];
    at[0] = pose.root_position;
    for (int i = 1; i < n; ++i) {
      at[i] = at[i - 1] + world[i - 1] * body_.offset(chain_[i]);
      world[i] = world[i - 1] * pose.rotations[chain_[i]];
    }
    head_at = at[n - 1] + world[n - 1] * body_.offset(body_.head());
  };
  // Signed angle about the pelvis-head line from the current skullbase X to the wanted one.
  auto remaining = [&] {
    const Eigen::Vector3d u = (head_at - at[0]).normalized();
    auto across = [&](const Eigen::Vector3d& x) { return Eigen::Vector3d(x - x.dot(u) * u); };
    const Eigen::Vector3d now = across(world[n - 1] * Eigen::Vector3d::UnitX());
    const Eigen::Vector3d want = across(head * Eigen::Vector3d::UnitX());
    return std::atan2(now.cross(want).dot(u), now.dot(want));
  };
  forward();
  if ((head_at - at[0]).norm() < 1e-9 || n < 2) return;
  double angle = remaining();
  for (int sweep = 0; sweep < kMaxSweeps && std::abs(angle) > kTwistError; ++sweep) {
    for (int i = 1; i < n; ++i) {
      const Eigen::Vector3d axis = head_at - at[i];
      if (axis.norm() < 1e-9) continue;
      const Eigen::Quaterniond turn(Eigen::AngleAxisd(angle / (n - 1), axis.normalized()));
      Eigen::Quaterniond& local = pose.rotations[chain_[i]];
      local = (world[i - 1].conjugate() * turn * world[i - 1] * local).normalized();
      if (limits) local = limits_.clamp(chain_[i], local);
      forward();
    }
    angle = remaining();
  }
  pose.rotations[body_.head()] = (world[n - 1].conjugate() * head).normalized();
}

}  // namespace simcap
