#include "core/linalg/anderson.h"

#include <Eigen/QR>

namespace thinlayer {

Eigen::VectorXd AndersonAcceleration::next(const Eigen::VectorXd& x, const Eigen::VectorXd& G_x) {
  const Eigen::VectorXd f = G_x - x;
  residuals_.push_back(f);
  images_.push_back(G_x);
  if (static_cast<int>(residuals_.size()) > memory_ + 1) {
    residuals_.pop_front();
    images_.pop_front();
  }
  const int m = static_cast<int>(residuals_.size()) - 1;
  if (m < 1) return G_x;
  Eigen::MatrixXd dF(f.size(), m), dG(f.size(), m);
  for (int j = 0; j < m; ++j) {
    dF.col(j) = residuals_[j + 1] - residuals_[j];
    dG.col(j) = images_[j + 1] - images_[j];
  }
  // Least squares by a rank-revealing QR: nearly dependent differences are dropped.
  const Eigen::VectorXd gamma = dF.colPivHouseholderQr().solve(f);
  return G_x - dG * gamma;
}

}  // namespace thinlayer
