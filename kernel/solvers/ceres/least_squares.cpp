// The only translation unit that includes Ceres.
#include "kernel/solvers/least_squares.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mechanist {
namespace {

class Residuals {
 public:
  explicit Residuals(const LeastSquaresProblem& problem) : problem_(problem) {}
  bool operator()(double const* const* parameters, double* residuals) const {
    return problem_.evaluate(parameters[0], residuals);
  }

 private:
  const LeastSquaresProblem& problem_;
};

}  // namespace

std::string_view ToString(LeastSquaresSummary::Status status) {
  switch (status) {
    case LeastSquaresSummary::Status::kConverged:
      return "converged";
    case LeastSquaresSummary::Status::kNoConvergence:
      return "no_convergence";
    case LeastSquaresSummary::Status::kFailure:
      return "failure";
  }
  return "failure";
}

LeastSquaresSummary SolveLeastSquares(const LeastSquaresProblem& problem, std::vector<double>* x) {
  const std::size_t n = x->size();
  const bool bounded = !problem.lower.empty() || !problem.upper.empty();
  if (bounded && (problem.lower.size() != n || problem.upper.size() != n)) {
    throw std::invalid_argument("SolveLeastSquares: one lower and one upper bound per variable");
  }
  for (std::size_t i = 0; bounded && i < n; ++i) {
    if (problem.lower[i] > problem.upper[i]) {
      throw std::invalid_argument("SolveLeastSquares: a lower bound exceeds its upper bound");
    }
    (*x)[i] = std::clamp((*x)[i], problem.lower[i], problem.upper[i]);
  }
  LeastSquaresSummary summary;
  if (n == 0 || problem.residuals == 0) {
    std::vector<double> r(problem.residuals);
    if (problem.residuals > 0 && problem.evaluate(x->data(), r.data())) {
      for (const double v : r) summary.initial_cost += 0.5 * v * v;
    }
    summary.final_cost = summary.initial_cost;
    summary.message = "nothing to solve";
    return summary;
  }
  // Ceres' projected Levenberg-Marquardt can stall beside a bound (its steps, cut at the
  // bound, shrink until the parameter tolerance stops it), so the variables that end on a
  // bound are held there and the others solved again, until that set stays the same.
  std::vector<int> held;
  for (int round = 0; round <= static_cast<int>(n); ++round) {
    auto* cost = new ceres::DynamicNumericDiffCostFunction<Residuals, ceres::CENTRAL>(
        new Residuals(problem));
    cost->AddParameterBlock(static_cast<int>(n));
    cost->SetNumResiduals(static_cast<int>(problem.residuals));
    ceres::Problem solver_problem;
    solver_problem.AddResidualBlock(cost, nullptr, x->data());
    if (!held.empty()) {
      solver_problem.SetManifold(x->data(), new ceres::SubsetManifold(static_cast<int>(n), held));
    }
    for (std::size_t i = 0; bounded && i < n; ++i) {
      if (std::isfinite(problem.lower[i])) {
        solver_problem.SetParameterLowerBound(x->data(), static_cast<int>(i), problem.lower[i]);
      }
      if (std::isfinite(problem.upper[i])) {
        solver_problem.SetParameterUpperBound(x->data(), static_cast<int>(i), problem.upper[i]);
      }
    }
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.logging_type = ceres::SILENT;
    options.max_num_iterations = 200;
    options.function_tolerance = 1e-14;
    options.gradient_tolerance = 1e-14;
    options.parameter_tolerance = 1e-12;
    options.num_threads = 1;  // deterministic
    ceres::Solver::Summary result;
    ceres::Solve(options, &solver_problem, &result);
    if (round == 0) summary.initial_cost = result.initial_cost;
    summary.status = result.termination_type == ceres::CONVERGENCE
                         ? LeastSquaresSummary::Status::kConverged
                     : result.termination_type == ceres::NO_CONVERGENCE
                         ? LeastSquaresSummary::Status::kNoConvergence
                         : LeastSquaresSummary::Status::kFailure;
    summary.message = result.message;
    summary.iterations += static_cast<int>(result.iterations.size());
    summary.final_cost = result.final_cost;
    std::vector<int> at_bound;
    for (std::size_t i = 0; bounded && i < n; ++i) {
      const double eps = 1e-12 * std::max(1.0, std::abs((*x)[i]));
      if ((*x)[i] <= problem.lower[i] + eps || (*x)[i] >= problem.upper[i] - eps) {
        at_bound.push_back(static_cast<int>(i));
      }
    }
    if (at_bound == held || at_bound.size() == n ||
        summary.status == LeastSquaresSummary::Status::kFailure) {
      break;
    }
    held = at_bound;
  }
  return summary;
}

}  // namespace mechanist
