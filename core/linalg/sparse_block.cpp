#include "core/linalg/sparse_block.h"

namespace thinlayer {

Eigen::SparseMatrix<double> sparse_block(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                         const std::vector<int>& cols) {
  std::vector<int> row_of(A.rows(), -1), col_of(A.cols(), -1);
  for (size_t i = 0; i < rows.size(); ++i) row_of[rows[i]] = static_cast<int>(i);
  for (size_t j = 0; j < cols.size(); ++j) col_of[cols[j]] = static_cast<int>(j);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it)
      if (row_of[it.row()] >= 0 && col_of[it.col()] >= 0) t.emplace_back(row_of[it.row()], col_of[it.col()], it.value());
  Eigen::SparseMatrix<double> out(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace thinlayer
