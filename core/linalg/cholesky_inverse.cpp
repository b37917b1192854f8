#include "core/linalg/cholesky_inverse.h"

#include <stdexcept>
#include <string>

#include <lapacke.h>

namespace thinlayer {

Eigen::MatrixXd cholesky_inverse(const Eigen::MatrixXd& L) {
  if (L.rows() != L.cols()) throw std::invalid_argument("cholesky_inverse: the factor is not square");
  const lapack_int n = static_cast<lapack_int>(L.rows());
  if (n == 0) return Eigen::MatrixXd(0, 0);
  Eigen::MatrixXd inverse = L;  // dpotri works in place; Eigen's storage is column-major
  const lapack_int info = LAPACKE_dpotri(LAPACK_COL_MAJOR, 'L', n, inverse.data(), n);
  if (info > 0)
    throw std::runtime_error("cholesky_inverse: the factor's diagonal entry " + std::to_string(info) +
                             " is zero (the matrix is singular)");
  if (info < 0) throw std::logic_error("cholesky_inverse: LAPACKE_dpotri refused argument " + std::to_string(-info));
  // dpotri fills the lower triangle only; mirror it, so that the result is exactly symmetric.
  inverse.triangularView<Eigen::StrictlyUpper>() = inverse.transpose();
  return inverse;
}

}  // namespace thinlayer
