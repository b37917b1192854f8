#pragma once
// A sparse LU (UMFPACK) of a square matrix whose pattern stays fixed while its values change: the
// contact problem's mixed system (core/solvers/mixed_system.h), whose status rows change from one
// active-set step to the next. The symbolic analysis (fill-reducing order) is done once; each
// factorisation is numeric only. Rows and columns are equilibrated (Ruiz sweeps: the mixed system
// mixes stiffnesses in daN/mm, compliances in mm/daN and a floating layer's film rows 1e-15 below
// the adherents'), and every solve is refined against the original matrix with residuals computed
// in extended precision (core/linalg/extended_products.h).
#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

class SparseLU {
 public:
  SparseLU();
  ~SparseLU();
  SparseLU(const SparseLU&) = delete;
  SparseLU& operator=(const SparseLU&) = delete;

  // Factors A (its pattern the same at every call; analysed at the first). False if A is singular
  // to working precision: a zero pivot, or rcond below the unit round-off (a floating body held by
  // nothing).
  bool factor(const Eigen::SparseMatrix<double>& A);
  // x with A x = b, refined twice with residuals in extended precision (long double). With
  // `at_round_off`: then on with double-double residuals until the correction, in the equilibrated
  // unknowns, is within one unit in the last place of their largest (x is then the exact solution
  // to double's rounding, normwise: *at_round_off = true) or stops shrinking (at most
  // max_refinements more). Long double alone stalls near κ 2⁻⁶⁴: a fine lap's mixed system
  // (κ ≥ 1.5e10) at 4e-13 relative, where one double-double step reaches 8e-17.
  static constexpr int max_refinements = 10;
  Eigen::VectorXd solve(const Eigen::VectorXd& b, bool* at_round_off = nullptr) const;
  // A lower bound of the 1-norm condition number of the equilibrated matrix, κ₁ ≥ ‖S‖₁ ‖v‖₁ / ‖S v‖₁
  // (S v evaluated in extended precision, so the bound holds for the v computed), v from inverse
  // iteration on SᵀS (three steps: six substitutions on the factors, no new factorisation), and that
  // v in A's own unknowns (x = C v): the motion A nearly leaves free. Requires a successful factor().
  struct NearNull {
    double condition = 0;
    Eigen::VectorXd x;
  };
  NearNull near_null() const;
  // UMFPACK's reciprocal condition estimate of the equilibrated matrix (the smallest over largest
  // |U_ii|: crude, for reports).
  double rcond() const { return rcond_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double rcond_ = 0;
};

}  // namespace thinlayer
