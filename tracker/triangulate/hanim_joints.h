// The H-Anim joints a triangulated keypoint layout gives: keypoints whose twin is a joint centre
// directly, and the HE15 joints no detector marks (root, vc7, skullbase) placed geometrically.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/joint_track.h"
#include "models/keypoint_layouts.h"

namespace simcap::tracker {

// A joint placed in a frame spanned by keypoints: origin halfway between `left` and `right`,
// x towards `left`, y towards the mean of `toward` (orthogonalized), z = x × y, unit length the
// distance from the origin to that mean; `offset` are the joint's coordinates there on simcap's
// reference humanoid (build_humanoid(), 1.75 m, its skin for the face points), so the joint
// keeps its place in the body as the body turns, bends and scales.
struct DerivedJoint {
  std::string joint;
  std::string rule;  // for the notes and the diagnostics, e.g. "hips -> shoulders"
  std::array<int, 2> lateral{-1, -1};
  std::vector<int> toward;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

class HAnimJoints {
 public:
  // Throws Error naming the HE15 joints the layout can neither give nor derive.
  explicit HAnimJoints(const KeypointLayout& layout);

  // Measures the offsets again on a posed body whose H-Anim joints are known (the first frame's
  // ground truth under --init gt, as the other families size their bodies from it): a motion
  // capture's shoulder girdle does not sit where the neutral humanoid's does. Rules whose
  // keypoints or joint `truth` lacks (the face points) keep the reference humanoid's offsets.
  // Returns the joints measured again.
  std::vector<std::string> calibrate(const KeypointLayout& layout, const JointTrack& truth,
                                     int frame_index);

  // Output joints: the directly given ones in layout order, then the derived ones.
  const std::vector<std::string>& joints() const { return joints_; }
  const std::vector<DerivedJoint>& derived() const { return derived_; }
  // The joints' positions from the keypoints' (nullopt: missing); NaN where a joint's keypoints
  // are missing.
  std::vector<Eigen::Vector3d> place(
      const std::vector<std::optional<Eigen::Vector3d>>& keypoints) const;

 private:
  std::vector<std::string> joints_;
  std::vector<int> direct_;  // keypoint index of each directly given joint
  std::vector<DerivedJoint> derived_;
};

}  // namespace simcap::tracker
