#pragma once

// Eigen's dense decompositions that several sources need, instantiated in one source: each
// takes 5 to 15 s to compile wherever it is used.

#include <Eigen/Core>

namespace mechanist {

/// The least-squares solution x of A x = b, minimising |A x - b| (Householder QR with column
/// pivoting, Eigen's colPivHouseholderQr; a rank-deficient A gives one of the minimisers).
Eigen::VectorXd LinearLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

/// The unit vector x that minimises |m x|: the right singular vector of m's smallest singular
/// value (Eigen's JacobiSVD, thin V). Throws std::invalid_argument when m has fewer rows than
/// columns.
Eigen::VectorXd LeastSingularVector(const Eigen::MatrixXd& m);

/// An orthonormal basis of m's null space, as columns: the right singular vectors whose
/// singular values are at most `tolerance` (Eigen's JacobiSVD, full V).
Eigen::MatrixXd NullSpace(const Eigen::MatrixXd& m, double tolerance);

}  // namespace mechanist
