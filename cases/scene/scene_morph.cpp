#include "cases/scene/scene_morph.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/fem/linear_system.h"
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

// The elastic extension of one body's offsets: the displacement of every node (mm).
Eigen::MatrixX2d extend(const Mesh& mesh, const std::string& name, const NodeOffsets& offsets) {
  if (offsets.size() < 2)
    throw std::invalid_argument("moving body '" + name + "' for the layer needs at least two bondline nodes");
  Model model;
  // ν = 0.25 (λ = μ): the shape of the extension, not any real material's answer.
  model.bodies.push_back({name, mesh, Material{1.0, 1.0, PlaneHypothesis::Strain}});
  for (const auto& [node, d] : offsets)
    for (int c = 0; c < 2; ++c) model.dirichlet.push_back({"offset", 0, {node}, c, d[c]});
  const LinearSystem system(model);
  Eigen::VectorXd u_free;
  if (system.num_free() > 0) u_free = SparseCholesky(system.K()).solve(system.F());
  const Eigen::VectorXd u = system.expand(u_free);
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
    const Eigen::MatrixX2d d = extend(meshes[b], names[b], offsets[b]);
    first_inversion(meshes[b], meshes[b].quads, d, names[b], out);
    first_inversion(meshes[b], meshes[b].triangles, d, names[b], out);
    out.meshes[b].nodes += d;
  }
  return out;
}

}  // namespace thinlayer
