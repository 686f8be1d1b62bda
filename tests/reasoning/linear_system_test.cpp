#include "reasoning/linear_system.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <random>

namespace mechanist {
namespace {

using Row = LinearSystem::Row;

ExactReal Evaluate(const Row& row, const std::vector<ExactReal>& x) {
  ExactReal sum;
  for (const auto& t : row) sum += t.coefficient * x[t.variable];
  return sum;
}

// Oracle: the rank of random sparse integer systems from Eigen's full-pivot LU, and every
// solution checked exactly against every row.
TEST(LinearSystem, RankAndSolutionsMatchDenseOracleExactly) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 2 + static_cast<int>(rng() % 9);
    const int m = 1 + static_cast<int>(rng() % 12);
    std::vector<Row> rows;
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(m, n);
    for (int i = 0; i < m; ++i) {
      Row row;
      const int terms = 1 + static_cast<int>(rng() % 3);
      for (int k = 0; k < terms; ++k) {
        const int v = static_cast<int>(rng() % n);
        const int c = static_cast<int>(rng() % 7) - 3;
        if (c == 0) continue;
        row.push_back({static_cast<std::size_t>(v), Rational(c)});
        dense(i, v) += c;
      }
      // Some rows repeat combinations of earlier ones, so that redundancy occurs.
      if (i >= 2 && rng() % 3 == 0) {
        row.clear();
        dense.row(i) = dense.row(i - 1) - 2 * dense.row(i - 2);
        for (int v = 0; v < n; ++v) {
          if (dense(i, v) != 0)
            row.push_back({static_cast<std::size_t>(v), Rational(static_cast<int>(dense(i, v)))});
        }
      }
      rows.push_back(row);
    }
    LinearSystem system(static_cast<std::size_t>(n), 1e-9);
    int redundant = 0;
    for (const Row& r : rows) {
      if (system.AddRow(r) == LinearSystem::Outcome::kRedundant) ++redundant;
    }
    Eigen::FullPivLU<Eigen::MatrixXd> lu(dense);
    ASSERT_EQ(static_cast<long>(system.rank()), lu.rank()) << "trial " << trial;
    EXPECT_EQ(redundant, m - static_cast<int>(lu.rank()));
    const std::vector<Row> basis = system.NullSpace();
    ASSERT_EQ(basis.size(), system.nullity());
    // Each basis vector sets its own free variable at 1 and every other free variable at 0.
    const std::vector<std::size_t> free = system.FreeVariables();
    ASSERT_EQ(free.size(), basis.size());
    for (std::size_t k = 0; k < basis.size(); ++k) {
      for (std::size_t j = 0; j < free.size(); ++j) {
        const auto term = std::find_if(basis[k].begin(), basis[k].end(),
                                       [&](const auto& t) { return t.variable == free[j]; });
        if (j == k) {
          ASSERT_NE(term, basis[k].end());
          EXPECT_EQ(*term->coefficient.exact(), Rational(1));
        } else {
          EXPECT_TRUE(term == basis[k].end() || term->coefficient.exact()->is_zero());
        }
      }
    }
    for (const Row& b : basis) {
      std::vector<ExactReal> x(static_cast<std::size_t>(n));
      for (const auto& t : b) x[t.variable] = t.coefficient;
      for (const Row& r : rows) {
        const ExactReal v = Evaluate(r, x);
        ASSERT_TRUE(v.is_exact());
        EXPECT_TRUE(v.exact()->is_zero()) << "trial " << trial;
      }
    }
    // An inhomogeneous row: x0 = 1, when consistent, is met exactly by Solve().
    const auto outcome = system.AddRow({{0, Rational(1)}}, Rational(1));
    if (outcome != LinearSystem::Outcome::kInconsistent) {
      const std::vector<ExactReal> x = system.Solve();
      ASSERT_TRUE(x[0].is_exact());
      EXPECT_EQ(*x[0].exact(), Rational(1));
      for (const Row& r : rows) EXPECT_TRUE(Evaluate(r, x).exact()->is_zero());
    } else {
      EXPECT_TRUE(lu.rank() > 0);
    }
  }
}

TEST(LinearSystem, ContradictionIsReportedAndNotKept) {
  LinearSystem s(2, 1e-9);
  EXPECT_EQ(s.AddRow({{0, Rational(1)}, {1, Rational(-1)}}), LinearSystem::Outcome::kIndependent);
  EXPECT_EQ(s.AddRow({{0, Rational(1)}}, Rational(1)), LinearSystem::Outcome::kIndependent);
  EXPECT_EQ(s.AddRow({{1, Rational(1)}}, Rational(2)), LinearSystem::Outcome::kInconsistent);
  EXPECT_EQ(s.rank(), 2u);
  const auto x = s.Solve();
  EXPECT_EQ(*x[1].exact(), Rational(1));
}

TEST(LinearSystem, ApproximateCoefficientsStayApproximate) {
  LinearSystem s(2, 1e-9);
  s.AddRow({{0, ExactReal::Approximate(3.14159)}, {1, Rational(-1)}});
  s.AddRow({{0, Rational(1)}}, Rational(1));
  const auto x = s.Solve();
  EXPECT_FALSE(x[1].is_exact());
  EXPECT_NEAR(x[1].value(), 3.14159, 1e-12);
  EXPECT_TRUE(x[0].is_exact());
}

// A row scaled by its approximate coefficient would make its exact ones approximate: a lead
// screw's row (carriage slide = 8 x screw turn) beside a lever arm the other rows hold still.
TEST(LinearSystem, AnApproximateCoefficientLeavesTheExactOnesOfItsRowExact) {
  LinearSystem s(3, 1e-9);
  s.AddRow({{0, Rational(1)}});  // the lever's turn is held
  s.AddRow({{0, ExactReal::Approximate(-135.0413602)}, {1, Rational(1)}, {2, Rational(-8)}});
  s.AddRow({{2, Rational(1)}}, Rational(1));  // the screw turns once
  const auto x = s.Solve();
  ASSERT_TRUE(x[1].is_exact());
  EXPECT_EQ(*x[1].exact(), Rational(8));
  EXPECT_EQ(*x[0].exact(), Rational(0));
}

}  // namespace
}  // namespace mechanist
