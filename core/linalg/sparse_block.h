#pragma once
// Rows `rows` and columns `cols` of a sparse matrix, as a new sparse matrix (row i of the result
// is row rows[i] of A, column j is column cols[j]). For the blocks the condensations cut out of a
// stiffness or constraint matrix once per scene; a principal block on the path of every solve has
// a faster, ordered variant in condensed_interface.cpp.
#include <vector>

#include <Eigen/SparseCore>

namespace thinlayer {

Eigen::SparseMatrix<double> sparse_block(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                         const std::vector<int>& cols);

}  // namespace thinlayer
