// SIK's spine (Unzueta 2009 §4.2, Alg. 8-9): bends or stretches the root-to-skullbase chain to the
// pelvis-head distance, orients the pelvis and splits the residual between both ends.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/name_table.h"
#include "models/pose.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_limits.h"

namespace simcap {

// How far the spine flexes when the pelvis-head line is shorter than the neutral spine.
// thesis: the whole flexion that makes the spine that short (eqs. 8-9). lean (not the thesis'):
// that flexion times the sine of the line's forward lean from the vertical (world +Y), all of
// it once the line leans past the horizontal, none when it leans back. A length alone does not
// say which way the spine bends (a few millimetres of shortening are as much an arched back as
// a rounded one), but a trunk leaning forward hangs on a flexed spine; the length left over is
// split between both ends as for a stretch.
enum class SikSpineBend { thesis, lean };
inline constexpr NameTable<SikSpineBend, 2> kSikSpineBends{
    {{"thesis", SikSpineBend::thesis}, {"lean", SikSpineBend::lean}}};

class SikSpine {
 public:
  // `body` and `limits` must outlive the spine.
  SikSpine(const SikBody& body, const SikLimits& limits, SikSpineBend bend = SikSpineBend::thesis);

  // Sets the rotations of the spine joints and the root's rotation and position in `pose`:
  // skullbase on the line from the pelvis target to the head target, the pelvis' X axis as close
  // to `pelvis_frame`'s as that allows, the length mismatch split evenly between both ends.
  void solve(const SikTargets& targets, const Eigen::Matrix3d& pelvis_frame, bool limits,
             Pose& pose);
  // Alg. 10-11 after solve(): turns the vertebrae about their lines to the skullbase, an equal
  // share each, until the skullbase's X axis meets `head`'s about the pelvis-head line (within
  // 0.01 rad, 20 sweeps, each vertebra kept in its limits), then sets the skullbase to `head`
  // (world). The neck is not measured separately (the thesis then takes the head's).
  void twist_to_head(const Eigen::Quaterniond& head, bool limits, Pose& pose) const;
  // Forgets the previous frame (the bend that the next search starts from).
  void reset();

 private:
  // The spine shape for root bend `phi_root` (thesis eqs. 8-9) written into `rotations`
  // (indexed like spine()), and the root-to-skullbase vector it gives with the root unrotated
  // in the world.
  Eigen::Vector3d bent(double phi_root, std::vector<Eigen::Quaterniond>& rotations) const;
  Eigen::Vector3d head_offset(const std::vector<Eigen::Quaterniond>& rotations) const;
  double search_bend(double target_length);
  // The share of the length-matching flexion that bend_ keeps for this pelvis frame (0..1).
  double flexion_share(const Eigen::Matrix3d& pelvis_frame) const;

  const SikBody& body_;
  const SikLimits& limits_;
  SikSpineBend bend_;
  std::vector<int> chain_;  // spine joints, root first
  double neutral_length_ = 0.0;
  double min_phi_root_ = 0.0;  // most flexed root angle the joint limits allow
  // Stretching postures (thesis: "precomputed stretching poses"): fractions 0..1 of the way
  // from neutral to every segment on the neutral root-head line, with their lengths.
  std::vector<std::vector<Eigen::Quaterniond>> stretch_;
  std::vector<double> stretch_length_;

  // Current length-matching bend of the root (<= 0: flexion; the others bend -2phi/m), where the
  // next search starts; the shape takes flexion_share() of it.
  double phi_root_ = 0.0;
  int stretch_index_ = 0;  // current stretching posture (0 = neutral)
  double current_length_ = 0.0;
  std::vector<Eigen::Quaterniond> shape_;  // scratch
};

}  // namespace simcap
