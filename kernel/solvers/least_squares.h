#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace mechanist {

/// A bounded nonlinear least-squares problem: minimise 1/2 |r(x)|^2 over lower <= x <= upper.
struct LeastSquaresProblem {
  std::size_t residuals = 0;  ///< the length of r
  /// Evaluates r(x) into `r`; returns false when x is outside the function's domain.
  std::function<bool(const double* x, double* r)> evaluate;
  /// Per variable; +-infinity for no bound. Empty: unbounded.
  std::vector<double> lower, upper;
};

/// How the solver ended, as data (Ceres' Solver::Summary, reduced).
struct LeastSquaresSummary {
  enum class Status {
    kConverged,      ///< a tolerance on the cost, gradient or step was reached
    kNoConvergence,  ///< the iteration limit was reached first
    kFailure         ///< the solver could not proceed (see `message`)
  };
  Status status = Status::kConverged;
  std::string message;
  int iterations = 0;
  double initial_cost = 0.0;  ///< 1/2 |r|^2 at the start
  double final_cost = 0.0;    ///< 1/2 |r|^2 at the solution
};

/// "converged", "no_convergence", "failure".
std::string_view ToString(LeastSquaresSummary::Status status);

/// Minimises from `x` (in: the start, clamped into the bounds; out: the solution) by
/// Levenberg-Marquardt in a trust region with the bounds as a box (Ceres behind this facade),
/// with derivatives by central differences. Variables that end on a bound are then held there
/// and the others solved again until that set stays the same (Ceres' projected steps stall
/// beside a bound); `iterations` counts all rounds. With no variables or no residuals it
/// returns at once. Throws std::invalid_argument when the bounds' sizes differ from x's or a lower
/// bound exceeds its upper bound.
LeastSquaresSummary SolveLeastSquares(const LeastSquaresProblem& problem, std::vector<double>* x);

}  // namespace mechanist
