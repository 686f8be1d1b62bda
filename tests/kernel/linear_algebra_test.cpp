#include "kernel/solvers/linear_algebra.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace mechanist {
namespace {

Eigen::MatrixXd Random(Eigen::Index rows, Eigen::Index cols, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) m(i, j) = normal(rng);
  }
  return m;
}

TEST(LinearAlgebra, LeastSquaresSolvesTheNormalEquations) {
  std::mt19937 rng(7);
  const Eigen::MatrixXd A = Random(20, 4, rng);
  const Eigen::VectorXd b = Random(20, 1, rng);
  const Eigen::VectorXd x = LinearLeastSquares(A, b);
  // The oracle: A^T (A x - b) = 0 at the minimum.
  EXPECT_LT((A.transpose() * (A * x - b)).norm(), 1e-10);
  // An exact system is solved exactly.
  const Eigen::VectorXd truth = Eigen::Vector4d(1, -2, 3, 0.5);
  EXPECT_LT((LinearLeastSquares(A, A * truth) - truth).norm(), 1e-12);
}

TEST(LinearAlgebra, LeastSingularVectorIsTheNullVectorOfRowsSquareToIt) {
  std::mt19937 rng(11);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 2, -2) / 3;
  Eigen::MatrixXd rows = Random(10, 3, rng);
  for (Eigen::Index i = 0; i < rows.rows(); ++i) {
    rows.row(i) -= rows.row(i).dot(n) * n.transpose();  // square to n
  }
  const Eigen::VectorXd v = LeastSingularVector(rows);
  EXPECT_NEAR(v.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(v.dot(n)), 1.0, 1e-12);
  EXPECT_THROW(LeastSingularVector(Random(2, 3, rng)), std::invalid_argument);
}

TEST(LinearAlgebra, NullSpaceHasTheRankDeficiencysDimensionAndIsOrthonormal) {
  std::mt19937 rng(13);
  // Rank 2 in 5 columns: a null space of dimension 3.
  const Eigen::MatrixXd m = Random(6, 2, rng) * Random(2, 5, rng);
  const Eigen::MatrixXd N = NullSpace(m, 1e-9);
  ASSERT_EQ(N.rows(), 5);
  ASSERT_EQ(N.cols(), 3);
  EXPECT_LT((m * N).norm(), 1e-10);
  EXPECT_LT((N.transpose() * N - Eigen::MatrixXd::Identity(3, 3)).norm(), 1e-12);
  EXPECT_EQ(NullSpace(Random(6, 5, rng), 1e-9).cols(), 0);
}

}  // namespace
}  // namespace mechanist
