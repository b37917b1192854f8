#pragma once
// Solves A x = b for a square matrix that mixes compliances (mm/daN), stiffnesses (daN/mm) and
// plain coefficients, whose scales differ by up to 1e15 in the layer mode (the contact
// active-set systems of core/solvers/active_set.h): equilibrate rows and columns (Ruiz sweeps),
// factor once with partial pivoting, refine the solution against the original A with residuals
// computed in extended precision (core/linalg/extended_products.h), so that the refined solution
// carries the round-off of its own digits rather than that of the cancellation in b − A x.
// A large and mostly empty A (the layer's mixed systems: a dense block of contact rows, the
// layer's banded stiffness, sparse coupling) is factored by a sparse LU instead of a dense one:
// at 450 unknowns 1 ms against 8 ms, the same answer to round-off.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

// rcond, if given, receives an estimate of the reciprocal 1-norm condition number of the
// equilibrated matrix (LAPACK-style; 0 for a singular one).
Eigen::VectorXd solve_equilibrated(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double* rcond = nullptr);
// The same for a matrix assembled sparse (always factored by the sparse LU, the dense LU only if
// its pattern is structurally singular).
Eigen::VectorXd solve_equilibrated(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b,
                                   double* rcond = nullptr);

}  // namespace thinlayer
