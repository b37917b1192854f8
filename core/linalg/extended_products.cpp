#include "core/linalg/extended_products.h"

namespace thinlayer {

LongVector times(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& x) {
  LongVector y = LongVector::Zero(A.rows());
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) y[it.row()] += Long(it.value()) * Long(x[j]);
  return y;
}

LongVector transpose_times(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& x) {
  LongVector y = LongVector::Zero(A.cols());
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) y[j] += Long(it.value()) * Long(x[it.row()]);
  return y;
}

Eigen::VectorXd residual(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  return (b.cast<Long>() - times(A, x)).cast<double>();
}

Eigen::VectorXd residual(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x) {
  Eigen::VectorXd r(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i) {
    Long s = b[i];
    for (Eigen::Index j = 0; j < A.cols(); ++j) s -= Long(A(i, j)) * Long(x[j]);
    r[i] = static_cast<double>(s);
  }
  return r;
}

}  // namespace thinlayer
