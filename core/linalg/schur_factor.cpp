#include "core/linalg/schur_factor.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace thinlayer::schur {

std::vector<int> order_last(cholmod_sparse* A, const std::vector<int>& last, cholmod_common* common) {
  const int n = static_cast<int>(A->nrow);
  const int rest = n - static_cast<int>(last.size());
  // CAMD's constraint sets are ordered by increasing label: the others (0) before Γ (1).
  std::vector<int> set(n, 0);
  for (int i : last) set[i] = 1;
  std::vector<int> camd(n);
  if (!cholmod_camd(A, nullptr, 0, set.data(), camd.data(), common))
    throw std::runtime_error("SparseCholesky: CAMD ordering failed (CHOLMOD status " + std::to_string(common->status) +
                             ")");
  std::vector<int> perm(camd.begin(), camd.begin() + rest);
  if (std::any_of(perm.begin(), perm.end(), [&](int i) { return set[i] != 0; }))
    throw std::logic_error("SparseCholesky: CAMD did not order the constrained unknowns last");
  perm.insert(perm.end(), last.begin(), last.end());
  return perm;
}

Eigen::MatrixXd trailing_block(const cholmod_factor& L, int size) {
  if (!L.is_super || !L.is_ll || L.xtype != CHOLMOD_REAL || L.itype != CHOLMOD_INT)
    throw std::logic_error("SparseCholesky: the trailing block needs a real supernodal LL' factor");
  const int first = static_cast<int>(L.n) - size;  // the block is columns and rows [first, n)
  const int* super = static_cast<const int*>(L.super);
  const int* pi = static_cast<const int*>(L.pi);
  const int* px = static_cast<const int*>(L.px);
  const int* rows_of = static_cast<const int*>(L.s);
  const double* x = static_cast<const double*>(L.x);
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(size, size);
  for (size_t s = 0; s < L.nsuper; ++s) {
    if (super[s + 1] <= first) continue;  // wholly before the block
    const int* rows = rows_of + pi[s];
    const int nrows = pi[s + 1] - pi[s];
    const double* values = x + px[s];
    for (int c = std::max(super[s], first); c < super[s + 1]; ++c) {
      const int local = c - super[s];  // the supernode's column, and the row of its diagonal
      // From the diagonal down: the entries above it in the supernode's square part are not L's.
      for (int r = local; r < nrows; ++r) T(rows[r] - first, c - first) = values[r + static_cast<size_t>(local) * nrows];
    }
  }
  return T;
}

}  // namespace thinlayer::schur
