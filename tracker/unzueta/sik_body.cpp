#include "tracker/unzueta/sik_body.h"

#include <algorithm>

#include "core/error.h"

namespace simcap {
namespace {

// Joint centres closer than this are one point (CMU's lowerback sits on the hips' centre).
constexpr double kCoincident = 1e-6;

}  // namespace

SikBody::SikBody(Skeleton skeleton, const SikHingeAxes& hinges) : skeleton_(std::move(skeleton)) {
  const int n = skeleton_.size();
  if (n == 0 || skeleton_[0].name != "humanoid_root") {
    throw Error("SIK needs a skeleton whose first joint is humanoid_root");
  }
  parent_.resize(n);
  offset_.resize(n);
  segment_.assign(n, Eigen::Vector3d::Zero());
  for (int j = 0; j < n; ++j) {
    parent_[j] = skeleton_[j].parent;
    offset_[j] = skeleton_.offset(j);
  }
  head_ = skeleton_.require("skullbase");
  for (int j = head_; j > 0; j = parent_[j]) spine_.push_back(parent_[j]);
  std::reverse(spine_.begin(), spine_.end());

  // A chain joint's segment points at the first later chain joint with a distinct centre.
  auto set_segments = [&](const std::vector<int>& chain) {
    for (size_t i = 0; i + 1 < chain.size(); ++i) {
      for (size_t k = i + 1; k < chain.size(); ++k) {
        const Eigen::Vector3d d = skeleton_[chain[k]].center - skeleton_[chain[i]].center;
        if (d.norm() > kCoincident) {
          segment_[chain[i]] = d.normalized();
          break;
        }
      }
    }
  };
  std::vector<int> spine_chain = spine_;
  spine_chain.push_back(head_);
  set_segments(spine_chain);

  for (int side : {kLeft, kRight}) {
    const std::string s = side == kLeft ? "l_" : "r_";
    SikLimb& arm = arm_[side];
    arm.a = skeleton_.require(s + "shoulder");
    arm.b = skeleton_.require(s + "elbow");
    arm.c = skeleton_.require(s + "radiocarpal");
    arm.clavicle = skeleton_.find(s + "sternoclavicular");
    SikLimb& leg = leg_[side];
    leg.a = skeleton_.require(s + "hip");
    leg.b = skeleton_.require(s + "knee");
    leg.c = skeleton_.require(s + "talocrural");
    for (SikLimb* limb : {&arm, &leg}) {
      if (parent_[limb->b] != limb->a || parent_[limb->c] != limb->b) {
        throw Error("SIK: " + skeleton_[limb->c].name + " must be a grandchild of " +
                    skeleton_[limb->a].name + " through " + skeleton_[limb->b].name);
      }
      std::vector<int> chain = {limb->a, limb->b, limb->c};
      if (limb->clavicle >= 0) chain.insert(chain.begin(), limb->clavicle);
      set_segments(chain);
      const Eigen::Vector3d upper = segment_[limb->a], lower = segment_[limb->b];
      if (lower.isZero() || upper.isZero()) {
        throw Error("SIK: the " + skeleton_[limb->a].name + " limb has a zero-length bone");
      }
      // Elbows flex forward, knees backward (H-Anim faces +Z).
      const bool is_arm = limb == &arm;
      auto flexion_axis = [&](const Eigen::Vector3d& segment) {
        const Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();
        const Eigen::Vector3d axis = is_arm ? segment.cross(forward) : forward.cross(segment);
        if (axis.norm() < 0.1) {
          throw Error("SIK: the neutral " + skeleton_[limb->a].name +
                      " limb points to the front; H-Anim's neutral limbs hang down");
        }
        return Eigen::Vector3d(axis.normalized());
      };
      limb->swivel_axis = flexion_axis(upper);
      limb->hinge_axis = flexion_axis(lower);
      const std::optional<Eigen::Vector3d>& given = is_arm ? hinges.elbow[side] : hinges.knee[side];
      if (given) {
        Eigen::Vector3d axis = *given - given->dot(lower) * lower;
        if (axis.norm() < 0.1 * given->norm()) {
          throw Error("SIK: the hinge axis given for " + skeleton_[limb->b].name +
                      " runs along its bone");
        }
        axis.normalize();
        limb->hinge_axis = axis.dot(limb->hinge_axis) >= 0 ? axis : Eigen::Vector3d(-axis);
      }
    }
    if (arm.clavicle >= 0 && parent_[arm.a] != arm.clavicle) {
      throw Error("SIK: " + s + "shoulder must be a child of " + s + "sternoclavicular");
    }
  }
}

void SikBody::forward(const Pose& pose, std::vector<Eigen::Quaterniond>& rotation,
                      std::vector<Eigen::Vector3d>& position) const {
  const int n = size();
  rotation.resize(n);
  position.resize(n);
  rotation[0] = pose.rotations[0];
  position[0] = pose.root_position;
  for (int j = 1; j < n; ++j) {
    const int p = parent_[j];
    rotation[j] = rotation[p] * pose.rotations[j];
    position[j] = position[p] + rotation[p] * offset_[j];
  }
}

SikTargets SikBody::targets(const std::vector<Eigen::Vector3d>& position) const {
  SikTargets t;
  t.pelvis = position[root()];
  t.head = position[head_];
  for (int side : {kLeft, kRight}) {
    t.wrist[side] = position[arm_[side].c];
    t.ankle[side] = position[leg_[side].c];
  }
  return t;
}

}  // namespace simcap
