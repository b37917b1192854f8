#include "core/linalg/sparse_lu.h"

#include <algorithm>
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
constexpr int refinements = 2;    // with long-double residuals one step reaches the solution's round-off where the
                                  // condition is moderate; one more checks it

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
  // S x = b or Sᵀ x = b (sys: UMFPACK_A or UMFPACK_At) on the equilibrated matrix S, unrefined.
  Eigen::VectorXd scaled_solve(const Eigen::VectorXd& b, int sys) const {
    Eigen::VectorXd x(b.size());
    double local_info[UMFPACK_INFO];
    umfpack_di_solve(sys, Ap.data(), Ai.data(), scaled.valuePtr(), x.data(), b.data(), numeric, control, local_info);
    return x;
  }
  Eigen::VectorXd raw_solve(const Eigen::VectorXd& b) const {
    return col.cwiseProduct(scaled_solve(row.cwiseProduct(b), UMFPACK_A));
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
  return status == UMFPACK_OK && rcond_ >= std::numeric_limits<double>::epsilon();
}

Eigen::VectorXd SparseLU::solve(const Eigen::VectorXd& b, bool* at_round_off) const {
  const Impl& m = *impl_;
  Eigen::VectorXd x = m.raw_solve(b);
  for (int step = 0; step < refinements; ++step) x += m.raw_solve(residual(m.A, b, x));
  if (!at_round_off) return x;
  // The proof asked for: refine on with double-double residuals until the correction, in the
  // equilibrated unknowns (where the LU works, each of order one), is within one unit in the last
  // place of their largest — the normwise accuracy refinement attains where the residual is exact
  // enough (Higham, Accuracy and Stability, §12.1) — so that a further step moves the answer by
  // less than rounding it to double does; or until it stops shrinking (not shown, then).
  constexpr double u = 0.5 * std::numeric_limits<double>::epsilon();
  const auto scaled_size = [&](const Eigen::VectorXd& v) { return v.cwiseQuotient(m.col).cwiseAbs().maxCoeff(); };
  *at_round_off = false;
  double previous = INFINITY;
  for (int step = 0; step < max_refinements && x.allFinite(); ++step) {
    const Eigen::VectorXd dx = m.raw_solve(residual_double_double(m.A, b, x));
    const double size = scaled_size(dx);
    if (!(size < 0.5 * previous) && step > 0) break;  // no longer shrinking: as far as it goes
    x += dx;
    if (size <= 2 * u * scaled_size(x)) {
      *at_round_off = true;
      break;
    }
    previous = size;
  }
  return x;
}

SparseLU::NearNull SparseLU::near_null() const {
  const Impl& m = *impl_;
  const Eigen::Index n = m.scaled.rows();
  NearNull out;
  if (n == 0 || !m.numeric) return out;
  // A start with every sign pattern's weight (a fixed one: the estimate is reproducible).
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = 1.0 + 0.5 * std::sin(1.0 + 7.0 * static_cast<double>(i));
  for (int step = 0; step < 3; ++step) {
    const Eigen::VectorXd w = m.scaled_solve(v / v.norm(), UMFPACK_At);
    v = m.scaled_solve(w / w.norm(), UMFPACK_A);
    if (!v.allFinite()) return out;
  }
  double norm_S = 0;  // ‖S‖₁: the largest column sum
  for (int j = 0; j < m.scaled.outerSize(); ++j) {
    double sum = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(m.scaled, j); it; ++it) sum += std::abs(it.value());
    norm_S = std::max(norm_S, sum);
  }
  const double Sv = static_cast<double>(times(m.scaled, v).cwiseAbs().sum());
  out.condition = Sv > 0 ? std::min(norm_S * v.lpNorm<1>() / Sv, 1e300) : 1e300;
  out.x = m.col.cwiseProduct(v);
  return out;
}

}  // namespace thinlayer
