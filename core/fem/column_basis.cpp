#include "core/fem/column_basis.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>

#include "core/fem/element_q1.h"

namespace thinlayer {

std::optional<BandLayout> band_layout(const Mesh& mesh) {
  if (mesh.element != ElementType::Q1) return std::nullopt;
  const auto minus = mesh.node_sets.find("S-"), plus = mesh.node_sets.find("S+");
  if (minus == mesh.node_sets.end() || plus == mesh.node_sets.end()) return std::nullopt;
  const std::vector<int>& m = minus->second;
  const std::vector<int>& p = plus->second;
  if (m.size() < 2 || m.size() != p.size() || m[0] != 0) return std::nullopt;
  BandLayout layout{static_cast<int>(m.size()), p[0]};
  if (layout.across < 1 || mesh.num_nodes() != layout.columns * (layout.across + 1)) return std::nullopt;
  for (int i = 0; i < layout.columns; ++i)
    if (m[i] != layout.node(i, 0) || p[i] != layout.node(i, layout.across)) return std::nullopt;
  if (static_cast<int>(mesh.quads.size()) != (layout.columns - 1) * layout.across) return std::nullopt;
  for (const auto& cell : mesh.quads) {
    int lowest_column = layout.columns, lowest_level = layout.across + 1;
    for (int node : cell) {
      lowest_column = std::min(lowest_column, layout.column_of(node));
      lowest_level = std::min(lowest_level, layout.level_of(node));
    }
    for (int node : cell) {
      const int di = layout.column_of(node) - lowest_column, dj = layout.level_of(node) - lowest_level;
      if (di < 0 || di > 1 || dj < 0 || dj > 1) return std::nullopt;
    }
  }
  return layout;
}

namespace {

// The generalized DOFs of one cell: the translations of its two columns, then the relative
// displacements of its nodes above the minus face. Each is the sum of some of the cell's shape
// functions: a translation of all its column's nodes in the cell, a relative displacement of
// its own node.
struct CellBasis {
  std::vector<int> dofs;                // first z index of each (2 components)
  std::vector<std::vector<int>> nodes;  // the cell's local nodes (0..3) whose shape functions each sums
};

CellBasis cell_basis(const std::array<int, 4>& cell, const BandLayout& layout) {
  CellBasis basis;
  std::vector<int> columns;
  for (int node : cell)
    if (std::find(columns.begin(), columns.end(), layout.column_of(node)) == columns.end())
      columns.push_back(layout.column_of(node));
  for (int column : columns) {
    basis.dofs.push_back(layout.t(column));
    std::vector<int> members;
    for (int a = 0; a < 4; ++a)
      if (layout.column_of(cell[a]) == column) members.push_back(a);
    basis.nodes.push_back(members);
  }
  for (int a = 0; a < 4; ++a) {
    const int level = layout.level_of(cell[a]);
    if (level == 0) continue;
    basis.dofs.push_back(layout.v(layout.column_of(cell[a]), level));
    basis.nodes.push_back({a});
  }
  return basis;
}

// Adds ∫ B̃ᵀ D B̃ at one reference point with weight w to Ke.
void add_point(const Coords4& xy, const CellBasis& basis, double xi, double eta, double weight,
               const Eigen::Matrix3d& D, Eigen::MatrixXd& Ke) {
  const Eigen::Matrix<double, 2, 4> dN_ref = q1_reference_gradients(xi, eta);
  const Eigen::Matrix2d J = dN_ref * xy;  // J(i,j) = d x_j / d ref_i
  const double detJ = J.determinant();
  if (!(detJ > 0)) throw std::runtime_error("Q1 layer cell with non-positive Jacobian (inverted or degenerate cell)");
  const Eigen::Matrix2d J_inv = J.inverse();
  const int n = static_cast<int>(basis.nodes.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(3, 2 * n);
  for (int k = 0; k < n; ++k) {
    // The summed reference gradient: for a column's two nodes the through-thickness parts are
    // equal and opposite, so their sum is exactly zero before J⁻¹ mixes the directions.
    Eigen::Vector2d g_ref = Eigen::Vector2d::Zero();
    for (int a : basis.nodes[k]) g_ref += dN_ref.col(a);
    const Eigen::Vector2d g = J_inv * g_ref;
    B(0, 2 * k) = g.x();
    B(1, 2 * k + 1) = g.y();
    B(2, 2 * k) = g.y();
    B(2, 2 * k + 1) = g.x();
  }
  Ke += B.transpose() * D * B * (detJ * weight);
}

}  // namespace

Eigen::SparseMatrix<double> column_stiffness(const Mesh& mesh, const BandLayout& layout, const Material& material,
                                             bool selective_integration) {
  const Eigen::Matrix3d D = material.D();
  Eigen::Matrix3d D_volumetric = Eigen::Matrix3d::Zero();
  if (selective_integration) D_volumetric.topLeftCorner<2, 2>().setConstant(material.lambda);
  const Eigen::Matrix3d D_rest = D - D_volumetric;
  const double g = 1.0 / std::sqrt(3.0);
  std::vector<Eigen::Triplet<double>> triplets;
  for (const auto& cell : mesh.quads) {
    Coords4 xy;
    for (int a = 0; a < 4; ++a) xy.row(a) = mesh.nodes.row(cell[a]);
    const CellBasis basis = cell_basis(cell, layout);
    const int n = static_cast<int>(basis.dofs.size());
    Eigen::MatrixXd Ke = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    for (double xi : {-g, g})
      for (double eta : {-g, g}) add_point(xy, basis, xi, eta, 1.0, selective_integration ? D_rest : D, Ke);
    if (selective_integration) add_point(xy, basis, 0.0, 0.0, 4.0, D_volumetric, Ke);
    for (int a = 0; a < n; ++a)
      for (int ca = 0; ca < 2; ++ca)
        for (int b = 0; b < n; ++b)
          for (int cb = 0; cb < 2; ++cb)
            triplets.emplace_back(basis.dofs[a] + ca, basis.dofs[b] + cb, Ke(2 * a + ca, 2 * b + cb));
  }
  Eigen::SparseMatrix<double> K(layout.size(), layout.size());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

namespace {

template <typename Vector>
Vector to_columns(const Vector& nodal_forces, const BandLayout& layout) {
  Vector z = Vector::Zero(layout.size());
  for (int i = 0; i < layout.columns; ++i)
    for (int j = 0; j <= layout.across; ++j)
      for (int c = 0; c < 2; ++c) {
        const auto f = nodal_forces[2 * layout.node(i, j) + c];
        z[layout.t(i) + c] += f;
        if (j > 0) z[layout.v(i, j) + c] += f;
      }
  return z;
}

// sign −1: the inverse of column_forces; +1: its bound.
template <typename Vector>
Vector to_nodal(const Vector& column, const BandLayout& layout, double sign) {
  Vector f(2 * layout.columns * (layout.across + 1));
  for (int i = 0; i < layout.columns; ++i)
    for (int c = 0; c < 2; ++c) {
      auto foot = column[layout.t(i) + c];
      for (int j = 1; j <= layout.across; ++j) {
        f[2 * layout.node(i, j) + c] = column[layout.v(i, j) + c];
        foot += sign * column[layout.v(i, j) + c];
      }
      f[2 * layout.node(i, 0) + c] = foot;
    }
  return f;
}

}  // namespace

Eigen::VectorXd column_forces(const Eigen::VectorXd& nodal_forces, const BandLayout& layout) {
  return to_columns(nodal_forces, layout);
}

LongVector column_forces(const LongVector& nodal_forces, const BandLayout& layout) {
  return to_columns(nodal_forces, layout);
}

Eigen::VectorXd nodal_forces(const Eigen::VectorXd& column_forces, const BandLayout& layout) {
  return to_nodal(column_forces, layout, -1.0);
}

LongVector nodal_forces(const LongVector& column_forces, const BandLayout& layout) {
  return to_nodal(column_forces, layout, -1.0);
}

Eigen::VectorXd nodal_force_bound(const Eigen::VectorXd& column_bound, const BandLayout& layout) {
  return to_nodal(column_bound, layout, 1.0);
}

Eigen::VectorXd nodal_displacements(const Eigen::VectorXd& z, const BandLayout& layout) {
  Eigen::VectorXd u(2 * layout.columns * (layout.across + 1));
  for (int i = 0; i < layout.columns; ++i)
    for (int j = 0; j <= layout.across; ++j)
      for (int c = 0; c < 2; ++c)
        u[2 * layout.node(i, j) + c] = z[layout.t(i) + c] + (j > 0 ? z[layout.v(i, j) + c] : 0.0);
  return u;
}

}  // namespace thinlayer
