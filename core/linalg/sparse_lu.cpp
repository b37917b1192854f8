#include "core/linalg/sparse_lu.h"

#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>
#include <vector>

#include <umfpack.h>

#include "core/linalg/extended_products.h"
#include "core/linalg/ruiz_scaling.h"

namespace thinlayer {

namespace {

constexpr int ruiz_sweeps = 8;    // each halves the spread of the row and column maxima's logarithms
constexpr int refinements = 2;    // with extended residuals, one step reaches the solution's round-off; one more checks it

}  // namespace

struct SparseLU::Impl {
  void* symbolic = nullptr;
  void* numeric = nullptr;
  double control[UMFPACK_CONTROL];
  double info[UMFPACK_INFO];
  Eigen::SparseMatrix<double> A, scaled;  // the matrix as given, and equilibrated
  Eigen::VectorXd row, col;
  std::vector<int> Ap, Ai;

  Impl() {
    umfpack_di_defaults(control);
    control[UMFPACK_SCALE] = UMFPACK_SCALE_NONE;  // equilibrated here
    control[UMFPACK_IRSTEP] = 0;                   // refined here, with extended residuals
  }
  ~Impl() {
    if (numeric) umfpack_di_free_numeric(&numeric);
    if (symbolic) umfpack_di_free_symbolic(&symbolic);
  }
  Eigen::VectorXd raw_solve(const Eigen::VectorXd& b) const {
    const Eigen::VectorXd scaled_b = row.cwiseProduct(b);
    Eigen::VectorXd x(b.size());
    double local_info[UMFPACK_INFO];
    umfpack_di_solve(UMFPACK_A, Ap.data(), Ai.data(), scaled.valuePtr(), x.data(), scaled_b.data(), numeric, control,
                     local_info);
    return col.cwiseProduct(x);
  }
};

SparseLU::SparseLU() : impl_(std::make_unique<Impl>()) {}
SparseLU::~SparseLU() = default;

bool SparseLU::factor(const Eigen::SparseMatrix<double>& A) {
  Impl& m = *impl_;
  const int n = static_cast<int>(A.rows());
  if (m.symbolic && (m.A.rows() != A.rows() || m.A.nonZeros() != A.nonZeros()))
    throw std::logic_error("SparseLU: the pattern changed between factorisations");
  m.A = A;
  m.A.makeCompressed();
  ruiz_scaling(m.A, ruiz_sweeps, m.row, m.col);
  m.scaled = m.row.asDiagonal() * m.A * m.col.asDiagonal();
  m.scaled.makeCompressed();
  if (!m.symbolic) {
    m.Ap.assign(m.scaled.outerIndexPtr(), m.scaled.outerIndexPtr() + n + 1);
    m.Ai.assign(m.scaled.innerIndexPtr(), m.scaled.innerIndexPtr() + m.scaled.nonZeros());
    const int symbolic =
        umfpack_di_symbolic(n, n, m.Ap.data(), m.Ai.data(), m.scaled.valuePtr(), &m.symbolic, m.control, m.info);
    // Out of memory is std::bad_alloc, whatever the library: the command names the phase (exit 2).
    if (symbolic == UMFPACK_ERROR_out_of_memory) throw std::bad_alloc();
    if (symbolic != UMFPACK_OK) throw std::runtime_error("SparseLU: UMFPACK's symbolic analysis failed");
  }
  if (m.numeric) umfpack_di_free_numeric(&m.numeric);
  const int status =
      umfpack_di_numeric(m.Ap.data(), m.Ai.data(), m.scaled.valuePtr(), m.symbolic, &m.numeric, m.control, m.info);
  if (status == UMFPACK_ERROR_out_of_memory) throw std::bad_alloc();
  rcond_ = std::isfinite(m.info[UMFPACK_RCOND]) ? m.info[UMFPACK_RCOND] : 0.0;
  // A pivot below the unit round-off times the largest is one that rounding alone could have
  // made of an exact zero (the LU's backward error is of that order): singular to working
  // precision. UMFPACK reports only exact zeros as singular; a layer left floating free by its
  // statuses gives rcond 4e-19 and a finite, meaningless answer (MixedSystem.AFloatingLayerHeld…).
  numeric_status_ = status;
  return status == UMFPACK_OK && rcond_ >= std::numeric_limits<double>::epsilon();
}

bool SparseLU::factor_allowing_small_pivots(const Eigen::SparseMatrix<double>& A) {
  factor(A);
  return numeric_status_ == UMFPACK_OK;
}

Eigen::VectorXd SparseLU::solve(const Eigen::VectorXd& b) const {
  const Impl& m = *impl_;
  Eigen::VectorXd x = m.raw_solve(b);
  for (int step = 0; step < refinements; ++step) x += m.raw_solve(residual(m.A, b, x));
  return x;
}

Eigen::VectorXd SparseLU::solve_once_refined(const Eigen::VectorXd& b) const {
  const Impl& m = *impl_;
  Eigen::VectorXd x = m.raw_solve(b);
  x += m.raw_solve(b - m.A * x);
  return x;
}

}  // namespace thinlayer
