// Unzueta's Sequential Inverse Kinematics (thesis ch. 4, Alg. 7): a full-body H-Anim pose from
// pelvis, head, wrist and ankle positions, part by part, within joint limits, avoiding collisions.
#pragma once

#include <optional>

#include "models/body_mesh.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_collision.h"
#include "tracker/unzueta/sik_ik_solver.h"
#include "tracker/unzueta/sik_limb.h"
#include "tracker/unzueta/sik_limits.h"
#include "tracker/unzueta/sik_pelvis.h"
#include "tracker/unzueta/sik_spine.h"

namespace simcap {

// SIK as simcap runs it by default (ik-eval's sik and tgbsik, `track --method sik`): the thesis'
// estimate plus two cues it lacks, the pelvis heading from the pelvis' forward travel (weight 2)
// and the spine's flexion from the trunk's lean. They bring the CMU walk and hop within the
// thesis' Table 10 averages (UNZUETA.md, "SIK's defaults"); travel 0 and SikSpineBend::thesis
// give the thesis' SIK.
inline constexpr double kSikPelvisTravel = 2.0;

struct SikOptions {
  SikPelvisWeights pelvis_weights{.travel = kSikPelvisTravel};
  bool limits = true;  // apply the biomechanical limits of §4.5
  // neutral: SIK; least_rotation: the thesis' TGBSIK (SIK's pelvis, spine and clavicles, TGB limbs
  // with the swivel of least shoulder and hip rotation).
  SikSwivel swivel = SikSwivel::neutral;
  SikSpineBend spine_bend = SikSpineBend::lean;
};

class SikSolver final : public IkSolver {
 public:
  // Without collision avoidance (as in the thesis' Table 10, whose humanoids had no mesh).
  explicit SikSolver(SikBody body, SikOptions options = {});
  // With the collision avoidance of §4.6 against `mesh` (built around the body's skeleton in its
  // neutral pose) and the floor plane y = floor_y.
  SikSolver(SikBody body, const BodyMesh& mesh, SikOptions options = {}, double floor_y = 0.0);
  SikSolver(const SikSolver&) = delete;
  SikSolver& operator=(const SikSolver&) = delete;

  std::string_view name() const override {
    return options_.swivel == SikSwivel::neutral ? "sik" : "tgbsik";
  }
  const SikBody& body() const override { return body_; }
  const SikLimits& limits() const { return limits_; }
  const Pose& solve(const SikTargets& targets) override;
  void reset() override;

 private:
  SikOptions options_;
  SikBody body_;
  SikLimits limits_;
  std::optional<SikCollider> collider_;
  SikPelvisEstimator pelvis_;
  SikSpine spine_;
  SikLimbSolver limbs_;
  Pose pose_;
  SikWorld world_;
};

}  // namespace simcap
