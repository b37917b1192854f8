#include "core/linalg/sparse_cholesky.h"

#include <stdexcept>
#include <string>

#include <Eigen/CholmodSupport>

namespace thinlayer {

struct SparseCholesky::Impl {
  Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A)
    : impl_(std::make_unique<Impl>()), size_(static_cast<int>(A.rows())) {
  if (A.rows() != A.cols()) throw std::invalid_argument("SparseCholesky: matrix is not square");
  impl_->llt.compute(A);
  if (impl_->llt.info() != Eigen::Success)
    throw std::runtime_error("singular system: the stiffness matrix (" + std::to_string(A.rows()) +
                             " DOFs) is not positive definite; a body is free to move rigidly "
                             "(check its supports)");
}

SparseCholesky::~SparseCholesky() = default;

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  Eigen::VectorXd x = impl_->llt.solve(b);
  if (impl_->llt.info() != Eigen::Success) throw std::runtime_error("SparseCholesky: solve failed");
  return x;
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X = impl_->llt.solve(B);
  if (impl_->llt.info() != Eigen::Success) throw std::runtime_error("SparseCholesky: solve failed");
  return X;
}

}  // namespace thinlayer
