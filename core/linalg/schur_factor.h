#pragma once
// The two CHOLMOD-level steps behind SparseCholesky::trailing_factor() (sparse_cholesky.h):
// order a set of unknowns Γ last, and read the trailing Γ × Γ block of the numeric factor,
// which is the Cholesky factor of the Schur complement of the matrix onto Γ.
// Internal to core/linalg: only sparse_cholesky.cpp includes this header.
#include <vector>

#include <cholmod.h>
#include <Eigen/Core>

namespace thinlayer::schur {

// A fill-reducing permutation of the symmetric matrix A that ends with `last`, in the order
// given (CHOLMOD's convention: position k of the factor is unknown perm[k] of A). The other
// unknowns come first in CAMD's constrained minimum-degree order, which sees the whole
// graph, Γ included. Γ's own order does not matter for the fill: its block of the factor is
// dense, or block-diagonal with no fill between blocks (the bodies are disconnected).
std::vector<int> order_last(cholmod_sparse* A, const std::vector<int>& last, cholmod_common* common);

// The trailing size × size block of a numeric supernodal LL' factor, lower triangular, in the
// factor's own (permuted) order. Each supernode holds its columns [super[s], super[s+1]) as one
// dense column-major block: rows s[pi[s] .. pi[s+1]) (its own columns first, then the rows
// below, ascending), values at x[px[s]], leading dimension pi[s+1] - pi[s]. A supernode may
// straddle the start of the block (the last interior columns amalgamated with Γ's).
Eigen::MatrixXd trailing_block(const cholmod_factor& L, int size);

}  // namespace thinlayer::schur
