#include "kernel/solvers/linear_algebra.h"

#include <Eigen/Dense>
#include <stdexcept>

namespace mechanist {

Eigen::VectorXd LinearLeastSquares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  return A.colPivHouseholderQr().solve(b);
}

Eigen::VectorXd LeastSingularVector(const Eigen::MatrixXd& m) {
  if (m.rows() < m.cols()) throw std::invalid_argument("fewer rows than columns");
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinV);
  return svd.matrixV().col(m.cols() - 1);
}

Eigen::MatrixXd NullSpace(const Eigen::MatrixXd& m, double tolerance) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeFullV);
  const Eigen::Index rank = (svd.singularValues().array() > tolerance).count();
  return svd.matrixV().rightCols(m.cols() - rank);
}

}  // namespace mechanist
