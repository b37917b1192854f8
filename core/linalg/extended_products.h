#pragma once
// Products and residuals accumulated in extended precision (x87 long double: a 64-bit mantissa,
// 2^11 times finer than double). What they are for: a residual b − A x whose terms cancel to far
// below their own size — the SPEC residual of an answer (core/solvers/contact_problem.h), and the
// iterative refinement of a linear solve (core/linalg/equilibrated_solve.h), which reaches the
// solution's own round-off only when its residuals are computed more precisely than the solve
// (Moler 1967; Higham, Accuracy and Stability of Numerical Algorithms, §12.1).
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

using Long = long double;  // the extended type every sum here is carried in
using LongVector = Eigen::Matrix<Long, Eigen::Dynamic, 1>;

LongVector times(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& x);            // A x
LongVector transpose_times(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& x);  // Aᵀ x
// b − A x, each sum in extended precision, rounded to double at the end.
Eigen::VectorXd residual(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x);
Eigen::VectorXd residual(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, const Eigen::VectorXd& x);

}  // namespace thinlayer
