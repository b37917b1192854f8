#include "core/fem/element_p1.h"

#include <stdexcept>

namespace thinlayer {

Eigen::Matrix<double, 3, 6> p1_strain_matrix(const Coords3& xy, double& area) {
  const double x1 = xy(0, 0), y1 = xy(0, 1), x2 = xy(1, 0), y2 = xy(1, 1), x3 = xy(2, 0), y3 = xy(2, 1);
  const double two_a = (x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1);
  if (!(two_a > 0)) throw std::runtime_error("P1 element with non-positive area (inverted or degenerate cell)");
  area = 0.5 * two_a;
  const double b[3] = {y2 - y3, y3 - y1, y1 - y2};  // dN/dx * 2A
  const double c[3] = {x3 - x2, x1 - x3, x2 - x1};  // dN/dy * 2A
  Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
  for (int a = 0; a < 3; ++a) {
    B(0, 2 * a) = b[a] / two_a;
    B(1, 2 * a + 1) = c[a] / two_a;
    B(2, 2 * a) = c[a] / two_a;
    B(2, 2 * a + 1) = b[a] / two_a;
  }
  return B;
}

Matrix6d p1_stiffness(const Coords3& xy, const Eigen::Matrix3d& D) {
  double area = 0;
  const auto B = p1_strain_matrix(xy, area);
  return B.transpose() * D * B * area;
}

}  // namespace thinlayer
