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
// b − A x in double-double (each product exact by a fused multiply-add, the sums compensated: about
// 2⁻¹⁰⁴ relative to Σ|a_ij x_j|, where long double leaves 2⁻⁶⁴): what a refinement needs to reach
// double's rounding on a system of condition 1e10 and beyond, whose long-double residuals leave an
// error of about κ 2⁻⁶⁴ (measured: refinement of a fine lap's mixed system, κ ≥ 1.5e10, stalls at
// 4e-13 relative with them).
Eigen::VectorXd residual_double_double(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                                       const Eigen::VectorXd& x);

}  // namespace thinlayer
