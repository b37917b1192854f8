#include "core/linalg/ruiz_scaling.h"

#include <algorithm>
#include <cmath>

namespace thinlayer {

void ruiz_scaling(const Eigen::SparseMatrix<double>& A, int sweeps, Eigen::VectorXd& row, Eigen::VectorXd& col) {
  const Eigen::Index n = A.rows();
  row = Eigen::VectorXd::Ones(n);
  col = Eigen::VectorXd::Ones(A.cols());
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    Eigen::VectorXd row_max = Eigen::VectorXd::Zero(n), col_max = Eigen::VectorXd::Zero(A.cols());
    for (Eigen::Index j = 0; j < A.outerSize(); ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
        const double v = std::abs(row[it.row()] * it.value() * col[j]);
        row_max[it.row()] = std::max(row_max[it.row()], v);
        col_max[j] = std::max(col_max[j], v);
      }
    for (Eigen::Index i = 0; i < n; ++i)
      if (row_max[i] > 0) row[i] /= std::sqrt(row_max[i]);
    for (Eigen::Index j = 0; j < A.cols(); ++j)
      if (col_max[j] > 0) col[j] /= std::sqrt(col_max[j]);
  }
}

}  // namespace thinlayer
