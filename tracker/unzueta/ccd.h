// The CCD baseline of Unzueta's Table 10 (§4.7.1, after Wang & Chen 1991): SIK's pelvis estimate,
// then CCD on spine, clavicle+arm and leg chains from the previous frame, within SIK's limits.
#pragma once

#include <array>
#include <vector>

#include "tracker/unzueta/ik_baseline_options.h"
#include "tracker/unzueta/sik_body.h"
#include "tracker/unzueta/sik_ik_solver.h"
#include "tracker/unzueta/sik_limits.h"
#include "tracker/unzueta/sik_pelvis.h"

namespace simcap {

using CcdOptions = IkBaselineOptions;

class CcdSolver final : public IkSolver {
 public:
  explicit CcdSolver(SikBody body, CcdOptions options = {});
  CcdSolver(const CcdSolver&) = delete;
  CcdSolver& operator=(const CcdSolver&) = delete;

  std::string_view name() const override { return "ccd"; }
  const SikBody& body() const override { return body_; }
  const Pose& solve(const SikTargets& targets) override;
  void reset() override;

 private:
  // Sweeps `chain` (base first) toward putting `effector` on `target`.
  void descend(const std::vector<int>& chain, int effector, const Eigen::Vector3d& target);
  void update_world();

  CcdOptions options_;
  SikBody body_;
  SikLimits limits_;
  SikPelvisEstimator pelvis_;
  Pose pose_;
  std::vector<Eigen::Quaterniond> rotation_;
  std::vector<Eigen::Vector3d> position_;
  std::vector<int> spine_;                     // spine joints without the root
  std::array<std::vector<int>, 2> arm_, leg_;  // clavicle (if any), shoulder, elbow; hip, knee
};

}  // namespace simcap
