#include "core/fem/element_q1.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

namespace thinlayer {

Eigen::Matrix<double, 2, 4> q1_reference_gradients(double xi, double eta) {
  static const double xi_n[4] = {-1, 1, 1, -1};
  static const double eta_n[4] = {-1, -1, 1, 1};
  Eigen::Matrix<double, 2, 4> dN_ref;
  for (int a = 0; a < 4; ++a) {
    dN_ref(0, a) = 0.25 * xi_n[a] * (1 + eta_n[a] * eta);
    dN_ref(1, a) = 0.25 * eta_n[a] * (1 + xi_n[a] * xi);
  }
  return dN_ref;
}

Eigen::Matrix<double, 3, 8> q1_strain_matrix(const Coords4& xy, double xi, double eta, double& detJ) {
  const Eigen::Matrix<double, 2, 4> dN_ref = q1_reference_gradients(xi, eta);
  const Eigen::Matrix2d J = dN_ref * xy;  // J(i,j) = d x_j / d ref_i
  detJ = J.determinant();
  if (!(detJ > 0)) throw std::runtime_error("Q1 element with non-positive Jacobian (inverted or degenerate cell)");
  const Eigen::Matrix<double, 2, 4> dN = J.inverse() * dN_ref;
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    B(0, 2 * a) = dN(0, a);
    B(1, 2 * a + 1) = dN(1, a);
    B(2, 2 * a) = dN(1, a);
    B(2, 2 * a + 1) = dN(0, a);
  }
  return B;
}

Matrix8d q1_stiffness(const Coords4& xy, const Eigen::Matrix3d& D) {
  const double g = 1.0 / std::sqrt(3.0);
  Matrix8d K = Matrix8d::Zero();
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      double detJ = 0;
      const auto B = q1_strain_matrix(xy, xi, eta, detJ);
      K += B.transpose() * D * B * detJ;  // Gauss weights are 1
    }
  return K;
}

Matrix8d q1_stiffness_selective(const Coords4& xy, const Eigen::Matrix3d& D_volumetric,
                                const Eigen::Matrix3d& D_rest) {
  Matrix8d K = q1_stiffness(xy, D_rest);
  double detJ = 0;
  const auto B = q1_strain_matrix(xy, 0.0, 0.0, detJ);
  K += B.transpose() * D_volumetric * B * (4 * detJ);  // one point, weight 4
  return K;
}

}  // namespace thinlayer
