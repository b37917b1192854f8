#pragma once
// Ruiz equilibration (D. Ruiz, "A scaling algorithm to equilibrate both rows and columns norms in
// matrices", RAL-TR-2001-034): row and column scalings that bring every row's and column's largest
// entry of diag(row) A diag(col) near 1. Each sweep halves the spread of the logarithms of the row
// and column maxima, so a few sweeps tame the 1e12 spread between a film's through-thickness and
// in-plane stiffness before a sparse LU pivots on them.
#include <Eigen/SparseCore>

namespace thinlayer {

void ruiz_scaling(const Eigen::SparseMatrix<double>& A, int sweeps, Eigen::VectorXd& row, Eigen::VectorXd& col);

}  // namespace thinlayer
