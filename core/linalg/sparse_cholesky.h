#pragma once
// A CHOLMOD factorisation of a symmetric positive definite matrix, factored once and reused
// for every right-hand side (all scenes that share a bulk matrix share one of these).
//
// Optionally some unknowns Γ are ordered last (the interface DOFs of a body): the trailing
// block of the factor then is the Cholesky factor of the Schur complement of A onto Γ,
//   L_ΓΓ L_ΓΓᵀ = S = A_ΓΓ − A_ΓI A_II⁻¹ A_IΓ   (I the other unknowns),
// because with P A Pᵀ = L Lᵀ and Γ last the last block row of L Lᵀ reads
// A_ΓΓ = L_ΓI L_ΓIᵀ + L_ΓΓ L_ΓΓᵀ with L_ΓI = A_ΓI L_II⁻ᵀ. It costs nothing beyond the
// factorisation (core/linalg/schur_factor.h), where |Γ| dense solves would cost |Γ| solves.
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

class SparseCholesky {
 public:
  // Throws std::runtime_error naming the cause when the matrix is not positive definite
  // (a body free to move rigidly: missing supports, or a floating part of the model).
  // Only the lower triangle of A is read (A is symmetric).
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A);
  // The same, with the unknowns `last` (distinct indices of A) ordered last, in that order,
  // so that trailing_factor() is available. The rest keeps a fill-reducing order (CAMD).
  SparseCholesky(const Eigen::SparseMatrix<double>& A, const std::vector<int>& last);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Not thread-safe: the solves use the factor's CHOLMOD workspace (one factor per thread).
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  int size() const { return size_; }

  // The lower triangular L_ΓΓ (|last| × |last|, rows and columns in the order of `last`) with
  // L_ΓΓ L_ΓΓᵀ = A_ΓΓ − A_ΓI A_II⁻¹ A_IΓ. Empty (0 × 0) when no `last` was given.
  // Then x_Γᵀ S⁻¹ x_Γ = |L_ΓΓ⁻¹ x_Γ|²: one small dense triangular solve per use.
  const Eigen::MatrixXd& trailing_factor() const { return trailing_factor_; }

  // CHOLMOD's cheap reciprocal condition estimate from the factor's diagonal,
  // (min diag L / max diag L)² = smallest / largest pivot. Crude and optimistic: the pivots lie
  // in [λ_min, λ_max], so the true 1/cond₂(A) is never larger. A small value (say < 1e-12)
  // says the solves may have lost most of their digits; a value near 1 proves nothing.
  double rcond() const { return rcond_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
  Eigen::MatrixXd trailing_factor_;
  double rcond_ = 1;
};

}  // namespace thinlayer
