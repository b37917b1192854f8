#include "core/linalg/extended_products.h"

#include <cmath>
#include <vector>

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

namespace {

// A double-double number hi + lo, |lo| <= ulp(hi)/2, and the error-free transformations it is built
// from (Knuth's TwoSum; the product's error by a fused multiply-add).
struct DoubleDouble {
  double hi = 0, lo = 0;
  void add(double a) {
    const double s = hi + a, v = s - hi, e = (hi - (s - v)) + (a - v);
    hi = s;
    lo += e;
  }
  void add_product(double a, double b) {
    const double p = a * b;
    add(p);
    lo += std::fma(a, b, -p);
  }
};

}  // namespace

Eigen::VectorXd residual_double_double(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                                       const Eigen::VectorXd& x) {
  std::vector<DoubleDouble> r(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i) r[i].add(b[i]);
  for (int j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) r[it.row()].add_product(-it.value(), x[j]);
  Eigen::VectorXd out(A.rows());
  for (Eigen::Index i = 0; i < A.rows(); ++i) out[i] = r[i].hi + r[i].lo;
  return out;
}

}  // namespace thinlayer
