#include "core/linalg/sparse_cholesky.h"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

#include <cholmod.h>

#include "core/linalg/inverse_block.h"

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
    // CHOLMOD's own printing of an error would be a second line on stderr; the status says it.
    common.print = 0;
  }

  // Out of memory is std::bad_alloc, whatever the library: the command names the phase (exit 2).
  void throw_if_out_of_memory() const {
    if (common.status == CHOLMOD_OUT_OF_MEMORY || common.status == CHOLMOD_TOO_LARGE) throw std::bad_alloc();
  }
  ~Impl() {
    if (L) cholmod_free_factor(&L, &common);
    cholmod_finish(&common);
  }

  // Symbolic analysis with CHOLMOD's default orderings (postordered, as inverse_block needs).
  void analyze(cholmod_sparse* A) {
    L = cholmod_analyze(A, &common);
    throw_if_out_of_memory();
    if (!L) throw std::runtime_error("SparseCholesky: CHOLMOD analysis failed (status " + std::to_string(common.status) + ")");
  }

  void factorize(cholmod_sparse* A) {
    cholmod_factorize(A, L, &common);
    throw_if_out_of_memory();
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
    throw_if_out_of_memory();
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
  impl_->analyze(&a);
  impl_->factorize(&a);
  rcond_ = cholmod_rcond(impl_->L, &impl_->common);
}

SparseCholesky::~SparseCholesky() = default;

namespace {

// The columns `unknowns` of B, in that order.
Eigen::SparseMatrix<double> columns(const Eigen::SparseMatrix<double>& B, const std::vector<int>& unknowns) {
  Eigen::SparseMatrix<double> out(B.rows(), static_cast<Eigen::Index>(unknowns.size()));
  out.reserve(B.nonZeros());
  for (size_t j = 0; j < unknowns.size(); ++j) {
    const auto col = static_cast<Eigen::Index>(j);
    out.startVec(col);
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, unknowns[j]); it; ++it) out.insertBack(it.row(), col) = it.value();
  }
  out.finalize();
  return out;
}

// The lower triangle of W += B G Bᵀ, for a sparse m × k B with a few entries per row and
// column and a dense symmetric G: H = G Bᵀ (a column of G per entry of B), then
// W(r, c) += B(r, :) H(:, c) for r ≥ c. About 0.4 ms for the dovetail's two 370 × 370 blocks at
// h = 0.0125, where Eigen's dense × sparseᵀ and sparse × dense products took 1.9 ms.
void add_congruence_lower(const Eigen::SparseMatrix<double>& B, const Eigen::MatrixXd& G, Eigen::MatrixXd& W) {
  const Eigen::Index m = B.rows(), k = B.cols();
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(k, m);
  for (Eigen::Index j = 0; j < k; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator e(B, j); e; ++e) H.col(e.row()) += e.value() * G.col(j);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> by_row = B;
  const int* start = by_row.outerIndexPtr();
  const int* column = by_row.innerIndexPtr();
  const double* value = by_row.valuePtr();
  for (Eigen::Index c = 0; c < m; ++c) {
    const double* h = H.col(c).data();
    for (Eigen::Index r = c; r < m; ++r) {
      double sum = 0;
      for (int p = start[r]; p < start[r + 1]; ++p) sum += value[p] * h[column[p]];
      W(r, c) += sum;
    }
  }
}

}  // namespace

Eigen::MatrixXd SparseCholesky::inverse_congruence(const Eigen::SparseMatrix<double>& B) const {
  if (B.cols() != size_) throw std::invalid_argument("SparseCholesky: B's columns are not the matrix's unknowns");
  std::vector<int> touched;  // Γ: the unknowns B has an entry on
  for (int c = 0; c < B.outerSize(); ++c)
    if (Eigen::SparseMatrix<double>::InnerIterator(B, c)) touched.push_back(c);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(B.rows(), B.rows());
  // Σ over the trees (bodies) of B_t G_t B_tᵀ, G_t = (A⁻¹) on tree t's Γ.
  for (const inverse_block::Block& t : inverse_block::per_tree(*impl_->L, touched))
    add_congruence_lower(columns(B, t.unknowns), t.inverse, W);
  W.triangularView<Eigen::StrictlyUpper>() = W.transpose();  // exactly symmetric
  return W;
}

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
