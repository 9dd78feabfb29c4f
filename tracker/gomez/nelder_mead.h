// The downhill simplex of Nelder & Mead (1965) as Gomez Jauregui uses it (thesis §2.4.4.4:
// reflection, expansion, inside contraction, shrink towards the best vertex) inside a box: every
// new vertex is projected onto the joint-limit box. The objective returns two terms (region and
// edge energy); the minimized value is their weighted sum, and the weights may change between
// runs (regions first, then edges from the region step's final simplex) without re-evaluating.
#pragma once

#include <Eigen/Core>
#include <functional>
#include <vector>

namespace simcap::tracker::gomez {

struct NelderMeadOptions {
  double alpha = 1.0;  // reflection
  double gamma = 2.0;  // expansion
  double rho = 0.5;    // contraction
  double sigma = 0.5;  // shrink ("multiple contraction")
  // Converged when 2 |f_worst - f_best| / (|f_worst| + |f_best| + 1e-10) falls below this
  // (the thesis's fractional range, as in Numerical Recipes' amoeba).
  double tolerance = 1e-4;
};

class NelderMead {
 public:
  using Terms = Eigen::Vector2d;
  using Objective = std::function<Terms(const Eigen::VectorXd&)>;

  // `objective` must be safe to call from several threads (a simplex's first vertices and a
  // shrink are evaluated in parallel).
  NelderMead(Objective objective, Eigen::VectorXd lower, Eigen::VectorXd upper,
             const NelderMeadOptions& options = {});

  // The simplex x0, x0 + s_i e_i (a step that would leave the box goes the other way).
  void start(const Eigen::VectorXd& x0, const Eigen::VectorXd& steps);
  // A simplex of n + 1 given vertices (clamped to the box), evaluated here.
  void start(std::vector<Eigen::VectorXd> vertices);
  void set_weights(const Terms& weights);
  // Iterates until `max_evaluations` more evaluations are spent (a shrink may overrun by up to
  // n - 1) or the simplex converges; returns the evaluations made.
  int run(int max_evaluations);

  const Eigen::VectorXd& best() const { return points_[order_[0]]; }
  const Terms& best_terms() const { return terms_[order_[0]]; }
  double best_value() const { return value(order_[0]); }
  bool converged() const;
  int evaluations() const { return static_cast<int>(history_.size()); }
  // Every point evaluated since start(), with its terms, in evaluation order.
  const std::vector<Eigen::VectorXd>& history() const { return history_; }
  const std::vector<Terms>& history_terms() const { return history_terms_; }
  // The simplex's vertices, best first.
  std::vector<Eigen::VectorXd> vertices() const;

 private:
  double value(int vertex) const { return weights_.dot(terms_[vertex]); }
  double value_of(const Terms& t) const { return weights_.dot(t); }
  Terms evaluate(const Eigen::VectorXd& x);
  void evaluate_all(const std::vector<int>& vertices);
  void sort();
  Eigen::VectorXd clamp(Eigen::VectorXd x) const;

  Objective objective_;
  Eigen::VectorXd lower_, upper_;
  NelderMeadOptions options_;
  Terms weights_ = Terms(1.0, 1.0);
  std::vector<Eigen::VectorXd> points_;
  std::vector<Terms> terms_;
  std::vector<int> order_;  // vertex indices, best first
  std::vector<Eigen::VectorXd> history_;
  std::vector<Terms> history_terms_;
};

}  // namespace simcap::tracker::gomez
