#include "core/linalg/sparse_cholesky.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <cholmod.h>

#include "core/linalg/schur_factor.h"

namespace thinlayer {

namespace {

// CHOLMOD's view of an Eigen matrix (no copy): symmetric, lower triangle read. A must be
// compressed, column-major with int indices (Eigen's default SparseMatrix<double>).
cholmod_sparse view(const Eigen::SparseMatrix<double>& A) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(A.rows());
  s.ncol = static_cast<size_t>(A.cols());
  s.nzmax = static_cast<size_t>(A.nonZeros());
  s.p = const_cast<int*>(A.outerIndexPtr());
  s.i = const_cast<int*>(A.innerIndexPtr());
  s.x = const_cast<double*>(A.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

// A dense column-major block of rows × cols values (an Eigen vector or matrix), no copy.
cholmod_dense view(const double* values, Eigen::Index rows, Eigen::Index cols) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(rows);
  d.ncol = static_cast<size_t>(cols);
  d.nzmax = d.nrow * d.ncol;
  d.d = d.nrow;
  d.x = const_cast<double*>(values);
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

}  // namespace

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* L = nullptr;

  Impl() {
    cholmod_start(&common);
    // As Eigen's CholmodSupernodalLLT (used here before): always supernodal, factor left as is.
    common.supernodal = CHOLMOD_SUPERNODAL;
    common.final_asis = 1;
  }
  ~Impl() {
    if (L) cholmod_free_factor(&L, &common);
    cholmod_finish(&common);
  }

  // Symbolic analysis with CHOLMOD's default orderings, or with the given permutation as is.
  void analyze(cholmod_sparse* A, std::vector<int>* perm) {
    if (perm) {
      common.nmethods = 1;
      common.method[0].ordering = CHOLMOD_GIVEN;
      // No postordering: it would regroup the elimination tree by subtree, which moves
      // interior columns between Γ's ones (checked after the analysis all the same).
      common.postorder = 0;
    }
    L = perm ? cholmod_analyze_p(A, perm->data(), nullptr, 0, &common) : cholmod_analyze(A, &common);
    if (!L) throw std::runtime_error("SparseCholesky: CHOLMOD analysis failed (status " + std::to_string(common.status) + ")");
  }

  void factorize(cholmod_sparse* A) {
    cholmod_factorize(A, L, &common);
    if (common.status < 0)
      throw std::runtime_error("SparseCholesky: CHOLMOD factorisation failed (status " + std::to_string(common.status) +
                               ")");
    if (L->minor < L->n)
      throw std::runtime_error("singular system: the stiffness matrix (" + std::to_string(A->nrow) +
                               " DOFs) is not positive definite; a body is free to move rigidly "
                               "(check its supports)");
  }

  // X = A⁻¹ B for the column-major rows × cols block B, written to X (same shape).
  void solve(const double* B, Eigen::Index rows, Eigen::Index cols, double* X) {
    cholmod_dense b = view(B, rows, cols);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, L, &b, &common);
    if (!x) throw std::runtime_error("SparseCholesky: solve failed (CHOLMOD status " + std::to_string(common.status) + ")");
    std::copy_n(static_cast<const double*>(x->x), rows * cols, X);
    cholmod_free_dense(&x, &common);
  }
};

namespace {

void check_square(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols()) throw std::invalid_argument("SparseCholesky: matrix is not square");
}

// CHOLMOD reads compressed storage only: a compressed copy when A is not.
const Eigen::SparseMatrix<double>& compressed(const Eigen::SparseMatrix<double>& A, Eigen::SparseMatrix<double>& copy) {
  if (A.isCompressed()) return A;
  copy = A;
  copy.makeCompressed();
  return copy;
}

}  // namespace

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A)
    : impl_(std::make_unique<Impl>()), size_(static_cast<int>(A.rows())) {
  check_square(A);
  Eigen::SparseMatrix<double> copy;
  cholmod_sparse a = view(compressed(A, copy));
  impl_->analyze(&a, nullptr);
  impl_->factorize(&a);
  rcond_ = cholmod_rcond(impl_->L, &impl_->common);
}

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A, const std::vector<int>& last)
    : impl_(std::make_unique<Impl>()), size_(static_cast<int>(A.rows())) {
  check_square(A);
  std::vector<bool> seen(size_, false);
  for (int i : last) {
    if (i < 0 || i >= size_ || seen[i])
      throw std::invalid_argument("SparseCholesky: the unknowns ordered last must be distinct indices of the matrix");
    seen[i] = true;
  }
  Eigen::SparseMatrix<double> copy;
  cholmod_sparse a = view(compressed(A, copy));
  std::vector<int> perm = schur::order_last(&a, last, &impl_->common);
  impl_->analyze(&a, &perm);
  // The trailing block is only the Schur complement's factor if Γ really is last, in order.
  const int* used = static_cast<const int*>(impl_->L->Perm);
  const int first = size_ - static_cast<int>(last.size());
  for (size_t k = 0; k < last.size(); ++k)
    if (used[first + k] != last[k])
      throw std::logic_error("SparseCholesky: CHOLMOD reordered the unknowns meant to be last");
  impl_->factorize(&a);
  rcond_ = cholmod_rcond(impl_->L, &impl_->common);
  trailing_factor_ = schur::trailing_block(*impl_->L, static_cast<int>(last.size()));
}

SparseCholesky::~SparseCholesky() = default;

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  if (b.size() != size_) throw std::invalid_argument("SparseCholesky: right-hand side of the wrong size");
  Eigen::VectorXd x(size_);
  impl_->solve(b.data(), size_, 1, x.data());
  return x;
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& B) const {
  if (B.rows() != size_) throw std::invalid_argument("SparseCholesky: right-hand side of the wrong size");
  Eigen::MatrixXd X(size_, B.cols());
  impl_->solve(B.data(), size_, B.cols(), X.data());
  return X;
}

}  // namespace thinlayer
