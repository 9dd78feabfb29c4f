// Two-step Nelder-Mead registration (registration.h).
#include "tracker/gomez/registration.h"

#include <cmath>

#include "tracker/gomez/nelder_mead.h"

namespace simcap::tracker::gomez {

Registered register_pose(const PoseScorer& scorer, const FrameCues& cues, const State& start,
                         const RegistrationOptions& options, bool region_only) {
  const BodyDofs& dofs = scorer.dofs();
  NelderMead nm(
      [&](const Eigen::VectorXd& x) {
        const Energy e = scorer.energy_of(x, cues);
        return NelderMead::Terms(e.terms());
      },
      dofs.lower(), dofs.upper());
  nm.start(start, options.simplex_size * dofs.steps());
  const int total = std::max(1, options.evaluations);
  const int regions =
      region_only ? total : static_cast<int>(std::lround(options.region_share * total));
  nm.set_weights({1.0, 0.0});
  int used = nm.evaluations() + nm.run(std::max(0, regions - nm.evaluations()));
  if (!region_only && used < total) {
    if (nm.converged()) {
      const State from = nm.best();
      nm.start(from, options.edge_simplex_size * dofs.steps());
      used += nm.evaluations();
    }
    nm.set_weights({0.0, 1.0});
    used += nm.run(std::max(0, total - used));
  }
  // The result is the best point by the particle energy (both terms) seen in the last run.
  const auto& hx = nm.history();
  const auto& ht = nm.history_terms();
  size_t best = 0;
  for (size_t k = 1; k < hx.size(); ++k) {
    if ((region_only ? ht[k][0] : ht[k].sum()) < (region_only ? ht[best][0] : ht[best].sum())) {
      best = k;
    }
  }
  const ScoreOptions& so = scorer.options();
  return {
      hx[best],
      {so.sigma_region * std::sqrt(2 * ht[best][0]), so.sigma_edge_px * std::sqrt(2 * ht[best][1])},
      used};
}

}  // namespace simcap::tracker::gomez
