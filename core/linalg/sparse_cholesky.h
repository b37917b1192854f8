#pragma once
// A CHOLMOD factorisation of a symmetric positive definite matrix, factored once and reused
// for every right-hand side (all scenes that share a bulk matrix share one of these).
#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace thinlayer {

class SparseCholesky {
 public:
  // Throws std::runtime_error naming the cause when the matrix is not positive definite
  // (a body free to move rigidly: missing supports, or a floating part of the model).
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  int size() const { return size_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int size_ = 0;
};

}  // namespace thinlayer
