// The CCD and KMA baselines of Unzueta's Table 10 (§4.7.1): SIK's pelvis estimate, then CCD (Wang &
// Chen 1991) on the chains within SIK's limits; KMA (Kulpa et al. 2005) CCD on the spine only.
#pragma once

#include <array>
#include <vector>

#include "tracker/unzueta/ik_baseline_options.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_ik_solver.h"
#include "tracker/unzueta/sik_limb.h"
#include "tracker/unzueta/sik_limits.h"
#include "tracker/unzueta/sik_pelvis.h"

namespace simcap {

using CcdOptions = IkBaselineOptions;

enum class CcdVariant {
  // CCD on spine, clavicle+arm and leg chains, each frame from the previous one.
  ccd,
  // The thesis' KMA: every frame from the standing pose, CCD on the spine, clavicles unturned,
  // limbs by TGB with zero swivel (SikSwivel::reference).
  kma,
};

class CcdSolver final : public IkSolver {
 public:
  explicit CcdSolver(SikBody body, CcdOptions options = {}, CcdVariant variant = CcdVariant::ccd);
  CcdSolver(const CcdSolver&) = delete;
  CcdSolver& operator=(const CcdSolver&) = delete;

  std::string_view name() const override { return variant_ == CcdVariant::ccd ? "ccd" : "kma"; }
  const SikBody& body() const override { return body_; }
  const Pose& solve(const SikTargets& targets) override;
  void reset() override;

 private:
  // Sweeps `chain` (base first) toward putting `effector` on `target`.
  void descend(const std::vector<int>& chain, int effector, const Eigen::Vector3d& target);
  void update_world();

  CcdOptions options_;
  CcdVariant variant_;
  SikBody body_;
  SikLimits limits_;
  SikPelvisEstimator pelvis_;
  SikLimbSolver limbs_;
  Pose pose_;
  SikWorld world_;
  std::vector<Eigen::Quaterniond>& rotation_ = world_.rotation;
  std::vector<Eigen::Vector3d>& position_ = world_.position;
  std::vector<int> spine_;                     // spine joints without the root
  std::array<std::vector<int>, 2> arm_, leg_;  // clavicle (if any), shoulder, elbow; hip, knee
};

}  // namespace simcap
