#pragma once
// A thin layer's band of Q1 cells in a column basis (issue 13).
//
// In the nodal basis the stiffness of a film of thickness ε is dominated by its
// through-thickness terms (∝ 1/ε); its in-plane (membrane, bending) stiffness is a tiny
// difference of those huge entries: 1e-13 of them at ε = 1e-8, and the condensed face stiffness
// built from it had relative errors of 1e-4 (ε = 1e-8) on the film's translations, which is what
// decides where a film slides. In the column basis each column of nodes (a line across the
// layer) moves by the translation of its foot on the minus face plus each node's displacement
// relative to that foot:
//     u(i, j) = t_i + v_(i, j),   v_(i, 0) = 0.
// The strain of a column translation is the gradient of the column's summed shape function,
// whose through-thickness derivative is zero exactly, so the translations' (membrane) stiffness
// is integrated directly instead of being left over after a cancellation.
#include <optional>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/fem/material.h"
#include "core/linalg/extended_products.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

// The numbering of a band built by layer_band(): node (i, j) = i·(across + 1) + j, i the column
// along the band, j = 0 on the minus face … across on the plus face.
struct BandLayout {
  int columns = 0, across = 0;
  int node(int i, int j) const { return i * (across + 1) + j; }
  int column_of(int node) const { return node / (across + 1); }
  int level_of(int node) const { return node % (across + 1); }

  // The column basis z: t_i at 2i (2 components), then v_(i, j), j = 1 … across, at
  // 2·columns + 2·(i·across + j − 1).
  int t(int i) const { return 2 * i; }
  int v(int i, int j) const { return 2 * columns + 2 * (i * across + j - 1); }
  int size() const { return 2 * columns * (across + 1); }
};

// The layout of a mesh made by layer_band(), or nullopt for any other mesh: the node count,
// the face node sets "S-" and "S+" and every cell (two neighbouring columns, two neighbouring
// levels) must match the band's numbering.
std::optional<BandLayout> band_layout(const Mesh& mesh);

// The band's stiffness in the column basis (size layout.size(), per unit thickness, daN/mm),
// full 2×2 Gauss integration or, with selective_integration, the λ part at the cell centre (as
// assemble_stiffness does for the same body).
Eigen::SparseMatrix<double> column_stiffness(const Mesh& mesh, const BandLayout& layout, const Material& material,
                                             bool selective_integration);

// Nodal values (2 per node, in node order) to the column basis and back. Forces transform with
// the transpose of the displacements' map: a translation takes the sum of its column's forces.
Eigen::VectorXd column_forces(const Eigen::VectorXd& nodal_forces, const BandLayout& layout);
// The same maps in extended precision, for the residual's evaluation (core/solvers/contact_problem.h).
LongVector column_forces(const LongVector& nodal_forces, const BandLayout& layout);
LongVector nodal_forces(const LongVector& column_forces, const BandLayout& layout);
// The inverse of column_forces: the nodal forces whose column forces these are (a node above the
// foot takes its v force; the foot takes its column's t force less those). Exact maps of ±1
// sums, so a body's imbalance evaluated in the column basis keeps its digits in nodal form.
Eigen::VectorXd nodal_forces(const Eigen::VectorXd& column_forces, const BandLayout& layout);
// A bound on the nodal forces from bounds on their column forces (the same map with every sign +):
// how round-off in column forces carries over to nodal ones.
Eigen::VectorXd nodal_force_bound(const Eigen::VectorXd& column_bound, const BandLayout& layout);
Eigen::VectorXd nodal_displacements(const Eigen::VectorXd& z, const BandLayout& layout);

}  // namespace thinlayer
