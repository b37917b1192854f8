#include "cases/scene/scene_morph.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/fem/element_p1.h"
#include "core/fem/element_q1.h"
#include "core/fem/material.h"
#include "core/linalg/sparse_cholesky.h"

namespace thinlayer {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The smallest s > 0 with c0 + c1 s + c2 s² = 0, c0 > 0 (+inf if none).
double first_positive_root(double c0, double c1, double c2) {
  const double scale = std::abs(c0) + std::abs(c1) + std::abs(c2);
  if (std::abs(c2) <= 1e-14 * scale) return c1 < 0 ? -c0 / c1 : inf;
  const double disc = c1 * c1 - 4 * c2 * c0;
  if (disc < 0) return inf;
  // Stable: q = −(c1 + sign(c1) √disc) / 2, roots q / c2 and c0 / q.
  const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
  double best = inf;
  for (double root : {q / c2, q != 0 ? c0 / q : inf})
    if (root > 0) best = std::min(best, root);
  return best;
}

// Stiffening exponent χ of the extension: each cell's modulus is (A_mean / A_cell)^χ, so that the
// small cells (along the bondline, and at its ends, where the offset meets a free boundary and the
// extension's gradient is singular) move almost rigidly and the large ones absorb the strain
// (Jacobian-based stiffening, Tezduyar et al. 1992).
constexpr double kStiffening = 1.0;

template <std::size_t N>
double cell_area(const Mesh& mesh, const std::array<int, N>& cell) {
  double a = 0;
  for (std::size_t k = 0; k < N; ++k) {
    const int i = cell[k], j = cell[(k + 1) % N];
    a += 0.5 * (mesh.nodes(i, 0) * mesh.nodes(j, 1) - mesh.nodes(j, 0) * mesh.nodes(i, 1));
  }
  return a;
}

// The stiffness of the extension on every node's two DOFs (plane strain, λ = μ = 1 scaled per cell).
Eigen::SparseMatrix<double> extension_stiffness(const Mesh& mesh) {
  const Eigen::Matrix3d D = Material{1.0, 1.0, PlaneHypothesis::Strain}.D();
  double mean = 0;
  for (const auto& q : mesh.quads) mean += cell_area(mesh, q);
  for (const auto& t : mesh.triangles) mean += cell_area(mesh, t);
  mean /= std::max(1, mesh.num_cells());
  std::vector<Eigen::Triplet<double>> triplets;
  auto add = [&](const auto& cell, const auto& Ke) {
    const double scale = std::pow(mean / cell_area(mesh, cell), kStiffening);
    for (std::size_t a = 0; a < cell.size(); ++a)
      for (int ca = 0; ca < 2; ++ca)
        for (std::size_t b = 0; b < cell.size(); ++b)
          for (int cb = 0; cb < 2; ++cb)
            triplets.emplace_back(2 * cell[a] + ca, 2 * cell[b] + cb, scale * Ke(2 * a + ca, 2 * b + cb));
  };
  for (const auto& q : mesh.quads) {
    Coords4 xy;
    for (int a = 0; a < 4; ++a) xy.row(a) = mesh.nodes.row(q[a]);
    add(q, q1_stiffness(xy, D));
  }
  for (const auto& t : mesh.triangles) {
    Coords3 xy;
    for (int a = 0; a < 3; ++a) xy.row(a) = mesh.nodes.row(t[a]);
    add(t, p1_stiffness(xy, D));
  }
  Eigen::SparseMatrix<double> K(2 * mesh.num_nodes(), 2 * mesh.num_nodes());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

// The extension of one body's offsets: the displacement of every node (mm).
Eigen::MatrixX2d extend(const Mesh& mesh, const std::string& name, const NodeOffsets& offsets) {
  if (offsets.size() < 2)
    throw std::invalid_argument("moving body '" + name + "' for the layer needs at least two bondline nodes");
  const int n = 2 * mesh.num_nodes();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  std::vector<int> free_index(n, 0);
  for (const auto& [node, d] : offsets) {
    u.segment<2>(2 * node) = d;
    free_index[2 * node] = free_index[2 * node + 1] = -1;
  }
  int free = 0;
  for (int& i : free_index)
    if (i == 0) i = free++;
  // K_ff u_f = −K_fd u_d.
  const Eigen::SparseMatrix<double> K = extension_stiffness(mesh);
  std::vector<Eigen::Triplet<double>> ff;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(free);
  for (int col = 0; col < K.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, col); it; ++it) {
      const int i = free_index[it.row()], j = free_index[it.col()];
      if (i >= 0 && j >= 0) ff.emplace_back(i, j, it.value());
      else if (i >= 0) rhs[i] -= it.value() * u[it.col()];
    }
  if (free > 0) {
    Eigen::SparseMatrix<double> K_ff(free, free);
    K_ff.setFromTriplets(ff.begin(), ff.end());
    const Eigen::VectorXd u_f = SparseCholesky(K_ff).solve(rhs);
    for (int dof = 0; dof < n; ++dof)
      if (free_index[dof] >= 0) u[dof] = u_f[free_index[dof]];
  }
  Eigen::MatrixX2d out(mesh.num_nodes(), 2);
  for (int i = 0; i < mesh.num_nodes(); ++i) out.row(i) << u[2 * i], u[2 * i + 1];
  return out;
}

// The first inversion of any cell of `mesh` as the displacement d is scaled by s.
template <std::size_t N>
void first_inversion(const Mesh& mesh, const std::vector<std::array<int, N>>& cells, const Eigen::MatrixX2d& d,
                     const std::string& name, Morph& out) {
  for (const auto& cell : cells)
    for (std::size_t a = 0; a < N; ++a) {
      const int i = cell[a], next = cell[(a + 1) % N], prev = cell[(a + N - 1) % N];
      const Eigen::Vector2d e1 = (mesh.nodes.row(next) - mesh.nodes.row(i)).transpose();
      const Eigen::Vector2d e2 = (mesh.nodes.row(prev) - mesh.nodes.row(i)).transpose();
      const Eigen::Vector2d d1 = (d.row(next) - d.row(i)).transpose(), d2 = (d.row(prev) - d.row(i)).transpose();
      const double s = first_positive_root(cross(e1, e2), cross(d1, e2) + cross(e1, d2), cross(d1, d2));
      if (s < out.inversion_scale) {
        out.inversion_scale = s;
        out.inverting_body = name;
        out.inverting_cell_centre = Eigen::Vector2d::Zero();
        for (int v : cell) out.inverting_cell_centre += mesh.nodes.row(v).transpose() / static_cast<double>(N);
      }
    }
}

}  // namespace

Morph morph_bodies(const std::vector<Mesh>& meshes, const std::vector<std::string>& names,
                   const std::vector<NodeOffsets>& offsets) {
  if (offsets.size() != meshes.size() || names.size() != meshes.size())
    throw std::invalid_argument("morph_bodies: one list of offsets and one name per body");
  Morph out;
  out.meshes = meshes;
  out.inversion_scale = inf;
  for (std::size_t b = 0; b < meshes.size(); ++b) {
    if (offsets[b].empty()) continue;
    // Every offset the same (a straight bondline on a body free to move away): the body
    // translates, exactly — no solve, no round-off in its new coordinates.
    const Eigen::Vector2d first = offsets[b].begin()->second;
    bool translation = true;
    for (const auto& [node, d] : offsets[b]) translation = translation && (d - first).norm() <= 1e-12 * first.norm();
    if (translation && first.norm() > 0) {
      out.meshes[b].nodes.rowwise() += first.transpose();
      continue;
    }
    const Eigen::MatrixX2d d = extend(meshes[b], names[b], offsets[b]);
    first_inversion(meshes[b], meshes[b].quads, d, names[b], out);
    first_inversion(meshes[b], meshes[b].triangles, d, names[b], out);
    out.meshes[b].nodes += d;
  }
  return out;
}

}  // namespace thinlayer
