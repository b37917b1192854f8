#pragma once
// A CHOLMOD factorisation of a symmetric positive definite matrix, factored once and reused
// for every right-hand side (all scenes that share a bulk matrix share one of these), and for
// the block of the inverse that the condensation needs (inverse_congruence).
#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

class SparseCholesky {
 public:
  // Throws std::runtime_error naming the cause when the matrix is not positive definite
  // (a body free to move rigidly: missing supports, or a floating part of the model).
  // Only the lower triangle of A is read (A is symmetric).
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Not thread-safe: the solves use the factor's CHOLMOD workspace (one factor per thread).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  int size() const { return size_; }

  // B A⁻¹ Bᵀ (B.rows() × B.rows(), exactly symmetric) for a sparse B whose columns are A's
  // unknowns, as the Delassus operator W = B K⁻¹ Bᵀ. Only the block of A⁻¹ on the unknowns Γ
  // that B touches is formed, from this factor as it is (core/linalg/inverse_block.h): a forward
  // solve restricted to the paths from Γ to the roots, where B.rows() full solves would each
  // cost a solve. It reads the factor only.
  Eigen::MatrixXd inverse_congruence(const Eigen::SparseMatrix<double>& B) const;

  // CHOLMOD's cheap reciprocal condition estimate from the factor's diagonal,
  // (min diag L / max diag L)² = smallest / largest pivot. Crude and optimistic: the pivots lie
  // in [λ_min, λ_max], so the true 1/cond₂(A) is never larger. A small value (say < 1e-12)
  // says the solves may have lost most of their digits; a value near 1 proves nothing.
  double rcond() const { return rcond_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
  double rcond_ = 1;
};

}  // namespace thinlayer
