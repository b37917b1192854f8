#pragma once
// Linear triangle (P1), constant strain.
#include <Eigen/Core>

namespace thinlayer {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Coords3 = Eigen::Matrix<double, 3, 2>;

// Strain-displacement matrix (3×6) and the triangle's area.
Eigen::Matrix<double, 3, 6> p1_strain_matrix(const Coords3& xy, double& area);

// Element stiffness, DOF order (u1,u2) per node (per unit thickness).
Matrix6d p1_stiffness(const Coords3& xy, const Eigen::Matrix3d& D);

}  // namespace thinlayer
