#pragma once
// Bilinear quadrilateral (Q1), full 2×2 Gauss integration.
#include <Eigen/Core>

namespace thinlayer {

using Matrix8d = Eigen::Matrix<double, 8, 8>;
using Coords4 = Eigen::Matrix<double, 4, 2>;

// Element stiffness, DOF order (u1,u2) per node in the cell's node order (per unit thickness).
Matrix8d q1_stiffness(const Coords4& xy, const Eigen::Matrix3d& D);

// Selective reduced integration: the λ (volumetric) part of D at the centre only, the rest
// with 2×2 Gauss points, D = D_volumetric + D_rest. Avoids volumetric locking of nearly
// incompressible elements.
Matrix8d q1_stiffness_selective(const Coords4& xy, const Eigen::Matrix3d& D_volumetric,
                                const Eigen::Matrix3d& D_rest);

// Gradients of the four shape functions with respect to the reference coordinates (xi, eta),
// one column per node (reference nodes (-1,-1), (1,-1), (1,1), (-1,1): a counter-clockwise cell).
Eigen::Matrix<double, 2, 4> q1_reference_gradients(double xi, double eta);

// Strain-displacement matrix B (3×8) at reference point (xi, eta) ∈ [-1,1]²; detJ returned.
Eigen::Matrix<double, 3, 8> q1_strain_matrix(const Coords4& xy, double xi, double eta, double& detJ);

}  // namespace thinlayer
