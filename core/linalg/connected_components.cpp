#include "core/linalg/connected_components.h"

#include <numeric>
#include <stdexcept>

namespace thinlayer {

std::vector<int> connected_components(const Eigen::SparseMatrix<double>& A) {
  if (A.rows() != A.cols()) throw std::invalid_argument("connected_components: the matrix is not square");
  const int n = static_cast<int>(A.rows());
  // Union–find with path halving: near-linear in the nonzeros.
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      const int a = root(static_cast<int>(it.row())), b = root(c);
      // The smaller root wins, so that a part's root is its smallest unknown.
      if (a < b) parent[b] = a;
      else if (b < a) parent[a] = b;
    }
  std::vector<int> part(n, -1);
  int parts = 0;
  for (int i = 0; i < n; ++i) {
    const int r = root(i);
    if (part[r] < 0) part[r] = parts++;
    part[i] = part[r];
  }
  return part;
}

}  // namespace thinlayer
