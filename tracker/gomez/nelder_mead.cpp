// Box-constrained Nelder-Mead (nelder_mead.h).
#include "tracker/gomez/nelder_mead.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace simcap::tracker::gomez {

NelderMead::NelderMead(Objective objective, Eigen::VectorXd lower, Eigen::VectorXd upper,
                       const NelderMeadOptions& options)
    : objective_(std::move(objective)),
      lower_(std::move(lower)),
      upper_(std::move(upper)),
      options_(options) {
  if (lower_.size() != upper_.size() || lower_.size() == 0) {
    throw Error("Nelder-Mead: the box needs equal, non-zero lower and upper sizes");
  }
}

Eigen::VectorXd NelderMead::clamp(Eigen::VectorXd x) const {
  return x.cwiseMax(lower_).cwiseMin(upper_);
}

NelderMead::Terms NelderMead::evaluate(const Eigen::VectorXd& x) {
  const Terms t = objective_(x);
  history_.push_back(x);
  history_terms_.push_back(t);
  return t;
}

void NelderMead::evaluate_all(const std::vector<int>& vertices) {
  std::vector<Terms> out(vertices.size());
  tbb::parallel_for(size_t{0}, vertices.size(),
                    [&](size_t k) { out[k] = objective_(points_[vertices[k]]); });
  for (size_t k = 0; k < vertices.size(); ++k) {
    terms_[vertices[k]] = out[k];
    history_.push_back(points_[vertices[k]]);
    history_terms_.push_back(out[k]);
  }
}

void NelderMead::start(const Eigen::VectorXd& x0, const Eigen::VectorXd& steps) {
  const int n = static_cast<int>(lower_.size());
  std::vector<Eigen::VectorXd> v(n + 1, clamp(x0));
  for (int i = 0; i < n; ++i) {
    const double up = v[0][i] + steps[i];
    v[i + 1][i] = up <= upper_[i] ? up : std::max(lower_[i], v[0][i] - steps[i]);
  }
  start(std::move(v));
}

void NelderMead::start(std::vector<Eigen::VectorXd> vertices) {
  if (vertices.size() != static_cast<size_t>(lower_.size()) + 1) {
    throw Error("Nelder-Mead: a simplex in " + std::to_string(lower_.size()) +
                " dimensions needs " + std::to_string(lower_.size() + 1) + " vertices, got " +
                std::to_string(vertices.size()));
  }
  history_.clear();
  history_terms_.clear();
  points_.clear();
  for (auto& x : vertices) points_.push_back(clamp(std::move(x)));
  terms_.assign(points_.size(), Terms::Zero());
  std::vector<int> all(points_.size());
  std::iota(all.begin(), all.end(), 0);
  evaluate_all(all);
  order_ = all;
  sort();
}

void NelderMead::set_weights(const Terms& weights) {
  weights_ = weights;
  if (!order_.empty()) sort();
}

void NelderMead::sort() {
  std::stable_sort(order_.begin(), order_.end(), [&](int a, int b) { return value(a) < value(b); });
}

bool NelderMead::converged() const {
  if (order_.empty()) return false;
  const double lo = value(order_.front()), hi = value(order_.back());
  return 2.0 * std::abs(hi - lo) <= options_.tolerance * (std::abs(hi) + std::abs(lo) + 1e-10);
}

std::vector<Eigen::VectorXd> NelderMead::vertices() const {
  std::vector<Eigen::VectorXd> out;
  for (const int i : order_) out.push_back(points_[i]);
  return out;
}

int NelderMead::run(int max_evaluations) {
  if (order_.empty()) throw Error("Nelder-Mead: run() before start()");
  const int n = static_cast<int>(lower_.size());
  const int begin = evaluations();
  while (evaluations() - begin < max_evaluations && !converged()) {
    const int worst = order_[n], best = order_[0];
    const double f_best = value(best), f_second = value(order_[n - 1]), f_worst = value(worst);
    Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < n; ++k) centroid += points_[order_[k]];
    centroid /= n;
    const Eigen::VectorXd xr = clamp(centroid + options_.alpha * (centroid - points_[worst]));
    const Terms tr = evaluate(xr);
    const double fr = value_of(tr);
    if (fr < f_best) {
      const Eigen::VectorXd xe = clamp(centroid + options_.gamma * (centroid - points_[worst]));
      const Terms te = evaluate(xe);
      if (value_of(te) < fr) {
        points_[worst] = xe;
        terms_[worst] = te;
      } else {
        points_[worst] = xr;
        terms_[worst] = tr;
      }
    } else if (fr < f_second) {
      points_[worst] = xr;
      terms_[worst] = tr;
    } else {
      const Eigen::VectorXd xc = clamp(points_[worst] + options_.rho * (centroid - points_[worst]));
      const Terms tc = evaluate(xc);
      if (value_of(tc) < f_worst) {
        points_[worst] = xc;
        terms_[worst] = tc;
      } else {
        std::vector<int> moved;
        for (int k = 1; k <= n; ++k) {
          const int i = order_[k];
          points_[i] = clamp(points_[best] + options_.sigma * (points_[i] - points_[best]));
          moved.push_back(i);
        }
        evaluate_all(moved);
      }
    }
    sort();
  }
  return evaluations() - begin;
}

}  // namespace simcap::tracker::gomez
