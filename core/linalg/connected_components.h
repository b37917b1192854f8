#pragma once
// The connected parts of a symmetric sparse matrix's graph (unknowns i, j joined where
// A(i, j) ≠ 0): the bodies of a stiffness matrix, which can then be factored one by one.
#include <vector>

#include <Eigen/SparseCore>

namespace thinlayer {

// The part of each unknown: 0, 1, … numbered in the order of each part's smallest unknown.
// Only the pattern is read, and both triangles (a stored zero joins its unknowns too).
std::vector<int> connected_components(const Eigen::SparseMatrix<double>& A);

}  // namespace thinlayer
