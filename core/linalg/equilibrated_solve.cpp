#include "core/linalg/equilibrated_solve.h"

#include <algorithm>
#include <cmath>

#include <Eigen/LU>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "core/linalg/extended_products.h"
#include "core/linalg/ruiz_scaling.h"

namespace thinlayer {

namespace {

constexpr int ruiz_sweeps = 5;
constexpr int refinements = 3;


// Hager's (Higham's) estimate of ‖M⁻¹‖₁ from solves with M and Mᵀ.
template <typename Solve, typename SolveTransposed>
double inverse_norm1_estimate(Eigen::Index n, Solve solve, SolveTransposed solve_transposed) {
  Eigen::VectorXd x = Eigen::VectorXd::Constant(n, 1.0 / static_cast<double>(n));
  double estimate = 0;
  for (int iteration = 0; iteration < 5; ++iteration) {
    const Eigen::VectorXd y = solve(x);
    estimate = y.lpNorm<1>();
    const Eigen::VectorXd xi = y.unaryExpr([](double v) { return v >= 0 ? 1.0 : -1.0; });
    const Eigen::VectorXd z = solve_transposed(xi);
    Eigen::Index j = 0;
    if (z.cwiseAbs().maxCoeff(&j) <= z.dot(x)) break;
    x.setZero();
    x[j] = 1;
  }
  return estimate;
}

}  // namespace

namespace {

// Sparse LU of the equilibrated matrix, refinement against A; false if the pattern is
// structurally singular.
bool sparse_solve(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& row, const Eigen::VectorXd& col,
                  const Eigen::VectorXd& b, Eigen::VectorXd& x, double* rcond) {
  const Eigen::SparseMatrix<double> M = row.asDiagonal() * A * col.asDiagonal();
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
  lu.compute(M);
  if (lu.info() != Eigen::Success) return false;
  auto solve = [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(lu.solve(v)); };
  x = col.asDiagonal() * solve(row.asDiagonal() * b);
  for (int refinement = 0; refinement < refinements; ++refinement)
    x += col.asDiagonal() * solve(row.asDiagonal() * residual(A, b, x));
  if (rcond) {
    double norm1 = 0;
    for (Eigen::Index j = 0; j < M.outerSize(); ++j) {
      double column = 0;
      for (Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it) column += std::abs(it.value());
      norm1 = std::max(norm1, column);
    }
    const double inverse = inverse_norm1_estimate(
        M.rows(), solve, [&](const Eigen::VectorXd& v) { return Eigen::VectorXd(lu.transpose().solve(v)); });
    *rcond = norm1 > 0 && std::isfinite(inverse) && inverse > 0 ? 1.0 / (norm1 * inverse) : 0.0;
  }
  return true;
}

Eigen::VectorXd dense_solve(const Eigen::MatrixXd& A, const Eigen::VectorXd& row, const Eigen::VectorXd& col,
                            const Eigen::VectorXd& b, double* rcond) {
  const Eigen::MatrixXd M = row.asDiagonal() * A * col.asDiagonal();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(M);
  if (rcond) *rcond = lu.rcond();
  Eigen::VectorXd x = col.asDiagonal() * lu.solve(row.asDiagonal() * b);
  for (int refinement = 0; refinement < refinements; ++refinement)
    x += col.asDiagonal() * lu.solve(row.asDiagonal() * residual(A, b, x));
  return x;
}

}  // namespace

Eigen::VectorXd solve_equilibrated(const Eigen::MatrixXd& A, const Eigen::VectorXd& b, double* rcond) {
  const Eigen::SparseMatrix<double> As = A.sparseView();
  if (A.rows() >= 200 && As.nonZeros() < A.size() / 4) return solve_equilibrated(As, b, rcond);
  Eigen::VectorXd row, col;
  ruiz_scaling(As, ruiz_sweeps, row, col);
  return dense_solve(A, row, col, b, rcond);
}

Eigen::VectorXd solve_equilibrated(const Eigen::SparseMatrix<double>& A, const Eigen::VectorXd& b, double* rcond) {
  Eigen::VectorXd row, col, x;
  ruiz_scaling(A, ruiz_sweeps, row, col);
  if (sparse_solve(A, row, col, b, x, rcond)) return x;
  return dense_solve(Eigen::MatrixXd(A), row, col, b, rcond);  // says how singular
}

}  // namespace thinlayer
