// The least-squares facade against closed-form optima.

#include "kernel/solvers/least_squares.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <random>

namespace mechanist {
namespace {

LeastSquaresProblem Rosenbrock() {
  LeastSquaresProblem p;
  p.residuals = 2;
  p.evaluate = [](const double* x, double* r) {
    r[0] = 1.0 - x[0];
    r[1] = 10.0 * (x[1] - x[0] * x[0]);
    return true;
  };
  return p;
}

TEST(LeastSquares, FindsRosenbrocksMinimum) {
  std::vector<double> x = {-1.2, 1.0};
  const LeastSquaresSummary s = SolveLeastSquares(Rosenbrock(), &x);
  EXPECT_EQ(s.status, LeastSquaresSummary::Status::kConverged) << s.message;
  EXPECT_NEAR(x[0], 1.0, 1e-7);
  EXPECT_NEAR(x[1], 1.0, 1e-7);
  EXPECT_LT(s.final_cost, 1e-15);
  EXPECT_GT(s.initial_cost, s.final_cost);
}

TEST(LeastSquares, StopsAtAnActiveBound) {
  // With x <= 1/2 the best is x = 1/2 (the first residual), y = x^2 (the second is zero).
  LeastSquaresProblem p = Rosenbrock();
  const double inf = std::numeric_limits<double>::infinity();
  p.lower = {-inf, -inf};
  p.upper = {0.5, inf};
  std::vector<double> x = {3.0, 0.0};  // outside: clamped in first
  const LeastSquaresSummary s = SolveLeastSquares(p, &x);
  EXPECT_EQ(s.status, LeastSquaresSummary::Status::kConverged) << s.message;
  EXPECT_NEAR(x[0], 0.5, 1e-9);
  EXPECT_NEAR(x[1], 0.25, 1e-7) << s.message << " after " << s.iterations;
}

TEST(LeastSquares, AgreesWithQrOnALinearProblem) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd A(12, 4);
  Eigen::VectorXd b(12);
  for (int i = 0; i < 12; ++i) {
    b[i] = normal(rng);
    for (int j = 0; j < 4; ++j) A(i, j) = normal(rng);
  }
  LeastSquaresProblem p;
  p.residuals = 12;
  p.evaluate = [&](const double* x, double* r) {
    Eigen::Map<Eigen::VectorXd>(r, 12) = A * Eigen::Map<const Eigen::VectorXd>(x, 4) - b;
    return true;
  };
  std::vector<double> x(4, 0.0);
  SolveLeastSquares(p, &x);
  const Eigen::VectorXd truth = A.colPivHouseholderQr().solve(b);
  for (int j = 0; j < 4; ++j) EXPECT_NEAR(x[j], truth[j], 1e-8);
}

TEST(LeastSquares, NothingToSolveAndBadBounds) {
  LeastSquaresProblem p;
  p.residuals = 1;
  p.evaluate = [](const double*, double* r) {
    r[0] = 2.0;
    return true;
  };
  std::vector<double> none;
  const LeastSquaresSummary s = SolveLeastSquares(p, &none);
  EXPECT_EQ(s.status, LeastSquaresSummary::Status::kConverged);
  EXPECT_DOUBLE_EQ(s.final_cost, 2.0);
  LeastSquaresProblem bad = Rosenbrock();
  bad.lower = {1.0, 0.0};
  bad.upper = {0.0, 1.0};
  std::vector<double> x = {0.0, 0.0};
  EXPECT_THROW(SolveLeastSquares(bad, &x), std::invalid_argument);
  bad.upper = {2.0};
  EXPECT_THROW(SolveLeastSquares(bad, &x), std::invalid_argument);
  EXPECT_EQ(ToString(LeastSquaresSummary::Status::kNoConvergence), "no_convergence");
}

}  // namespace
}  // namespace mechanist
