#include "tracker/triangulate/hanim_joints.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <limits>

#include "core/error.h"
#include "models/humanoid.h"
#include "tracker/triangulate/reference_body.h"

namespace simcap::tracker {
namespace {

struct Frame {
  Eigen::Vector3d origin;
  Eigen::Matrix3d axes;  // columns x, y, z
  double unit = 0;
};

std::optional<Frame> frame_of(const Eigen::Vector3d& left, const Eigen::Vector3d& right,
                              const Eigen::Vector3d& toward) {
  Frame f;
  f.origin = 0.5 * (left + right);
  const Eigen::Vector3d t = toward - f.origin;
  const Eigen::Vector3d x = (left - right).normalized();
  const Eigen::Vector3d y = t - t.dot(x) * x;
  f.unit = t.norm();
  if (!((left - right).norm() > 1e-9) || !(y.norm() > 1e-9)) return std::nullopt;
  f.axes.col(0) = x;
  f.axes.col(1) = y.normalized();
  f.axes.col(2) = x.cross(f.axes.col(1));
  return f;
}

struct Rule {
  const char* joint;
  const char* text;
  const char *left, *right;
  std::vector<std::string> toward;
};

// In order of preference per joint; the first whose anchors the layout has is used.
const std::vector<Rule>& rules() {
  static const std::vector<Rule> r = {
      {"humanoid_root",
       "hips -> shoulders",
       "left_hip",
       "right_hip",
       {"left_shoulder", "right_shoulder"}},
      {"vc7", "shoulders -> hips", "left_shoulder", "right_shoulder", {"left_hip", "right_hip"}},
      {"skullbase", "ears -> nose", "left_ear", "right_ear", {"nose"}},
      {"skullbase", "shoulders -> head top", "left_shoulder", "right_shoulder", {"Head"}},
  };
  return r;
}

}  // namespace

HAnimJoints::HAnimJoints(const KeypointLayout& layout) {
  for (int k = 0; k < layout.size(); ++k) {
    const LayoutKeypoint& kp = layout.keypoints[k];
    if (kp.truth != TruthKind::hanim_joint) continue;
    joints_.emplace_back(kp.truth_name);
    direct_.push_back(k);
  }
  const Anchors& ref = reference_anchors();
  for (const Rule& r : rules()) {
    if (std::find(joints_.begin(), joints_.end(), r.joint) != joints_.end()) continue;
    DerivedJoint d{r.joint,
                   r.text,
                   {keypoint_of(layout, r.left), keypoint_of(layout, r.right)},
                   {},
                   Eigen::Vector3d::Zero()};
    Eigen::Vector3d toward = Eigen::Vector3d::Zero();
    for (const std::string& t : r.toward) {
      d.toward.push_back(keypoint_of(layout, t));
      toward += ref.at(t) / static_cast<double>(r.toward.size());
    }
    if (d.lateral[0] < 0 || d.lateral[1] < 0 ||
        std::find(d.toward.begin(), d.toward.end(), -1) != d.toward.end()) {
      continue;
    }
    const auto f = frame_of(ref.at(r.left), ref.at(r.right), toward);
    if (!f) throw Error(std::string("reference humanoid: degenerate frame for ") + r.joint);
    d.offset = f->axes.transpose() * (ref.at(r.joint) - f->origin) / f->unit;
    joints_.push_back(d.joint);
    derived_.push_back(std::move(d));
  }
  std::string missing;
  for (const std::string& j : he15_joints()) {
    if (std::find(joints_.begin(), joints_.end(), j) == joints_.end()) {
      missing += (missing.empty() ? "" : ", ") + j;
    }
  }
  if (!missing.empty()) {
    throw Error(std::string("keypoint layout ") + std::string(layout.title) + " gives no H-Anim " +
                missing + " (the HE15 joints validate scores)");
  }
}

std::vector<std::string> HAnimJoints::calibrate(const KeypointLayout& layout,
                                                const JointTrack& truth, int frame_index) {
  const auto joint = [&](const std::string& name) -> std::optional<Eigen::Vector3d> {
    const int j = truth.joint_index(name);
    if (j < 0 || frame_index >= static_cast<int>(truth.positions.size())) return std::nullopt;
    const Eigen::Vector3d p = truth.positions[frame_index][j];
    return p.allFinite() ? std::optional(p) : std::nullopt;
  };
  const auto keypoint = [&](int k) -> std::optional<Eigen::Vector3d> {
    const LayoutKeypoint& kp = layout.keypoints[k];
    if (kp.truth != TruthKind::hanim_joint) return std::nullopt;
    return joint(std::string(kp.truth_name));
  };
  std::vector<std::string> measured;
  for (DerivedJoint& d : derived_) {
    const auto l = keypoint(d.lateral[0]), r = keypoint(d.lateral[1]), target = joint(d.joint);
    bool complete = l && r && target;
    Eigen::Vector3d toward = Eigen::Vector3d::Zero();
    for (const int t : d.toward) {
      const auto p = keypoint(t);
      complete = complete && p;
      if (p) toward += *p / static_cast<double>(d.toward.size());
    }
    const auto f = complete ? frame_of(*l, *r, toward) : std::nullopt;
    if (!f) continue;
    d.offset = f->axes.transpose() * (*target - f->origin) / f->unit;
    measured.push_back(d.joint);
  }
  return measured;
}

std::vector<Eigen::Vector3d> HAnimJoints::place(
    const std::vector<std::optional<Eigen::Vector3d>>& keypoints) const {
  const Eigen::Vector3d nan = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  std::vector<Eigen::Vector3d> out;
  out.reserve(joints_.size());
  const auto at = [&](int k) -> std::optional<Eigen::Vector3d> {
    return k >= 0 && k < static_cast<int>(keypoints.size()) ? keypoints[k] : std::nullopt;
  };
  for (const int k : direct_) out.push_back(at(k).value_or(nan));
  for (const DerivedJoint& d : derived_) {
    const auto l = at(d.lateral[0]), r = at(d.lateral[1]);
    Eigen::Vector3d toward = Eigen::Vector3d::Zero();
    bool complete = l && r;
    for (const int t : d.toward) {
      const auto p = at(t);
      complete = complete && p;
      if (p) toward += *p / static_cast<double>(d.toward.size());
    }
    const auto f = complete ? frame_of(*l, *r, toward) : std::nullopt;
    out.push_back(f ? Eigen::Vector3d(f->origin + f->unit * (f->axes * d.offset)) : nan);
  }
  return out;
}

}  // namespace simcap::tracker
