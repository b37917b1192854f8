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
  // The same, singular only where a pivot is exactly zero: for a matrix whose pivots legitimately
  // span more than the double range's digits (an interior-point method's barrier weights, 1e±20 by
  // the end of its path), where UMFPACK's rcond, the smallest over the largest pivot, says nothing
  // about the solve's accuracy (the refinement against the original matrix does).
  bool factor_allowing_small_pivots(const Eigen::SparseMatrix<double>& A);
  // x with A x = b, refined twice.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  // x with A x = b, refined once with the residual in double: a direction (an interior-point
  // method's), whose errors the next iteration's residuals see and correct, needs no more.
  Eigen::VectorXd solve_once_refined(const Eigen::VectorXd& b) const;
  // UMFPACK's reciprocal condition estimate of the equilibrated matrix (the smallest over largest
  // |U_ii|: crude, for reports).
  double rcond() const { return rcond_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double rcond_ = 0;
  int numeric_status_ = 0;
};

}  // namespace thinlayer
