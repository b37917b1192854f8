#include "core/fem/linear_system.h"

#include <algorithm>
#include <stdexcept>

#include "core/fem/element_p1.h"
#include "core/fem/element_q1.h"

namespace thinlayer {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

template <int NodesPerCell, typename Cell, typename StiffnessFn>
void add_cells(const std::vector<Cell>& cells, const Mesh& mesh, int offset, const Eigen::Matrix3d& D,
               StiffnessFn stiffness, Triplets& triplets) {
  Eigen::Matrix<double, NodesPerCell, 2> xy;
  for (const auto& cell : cells) {
    for (int a = 0; a < NodesPerCell; ++a) xy.row(a) = mesh.nodes.row(cell[a]);
    const auto Ke = stiffness(xy, D);
    for (int a = 0; a < NodesPerCell; ++a)
      for (int ca = 0; ca < 2; ++ca)
        for (int b = 0; b < NodesPerCell; ++b)
          for (int cb = 0; cb < 2; ++cb)
            triplets.emplace_back(offset + 2 * cell[a] + ca, offset + 2 * cell[b] + cb,
                                  Ke(2 * a + ca, 2 * b + cb));
  }
}

}  // namespace

SparseMatrix assemble_stiffness(const Model& model) {
  Triplets triplets;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const Body& body = model.bodies[b];
    const Eigen::Matrix3d D = body.material.D();
    const int offset = model.dof_offset(b);
    if (body.mesh.element == ElementType::Q1 && body.selective_integration) {
      // D = λ m mᵀ + (the μ part), m = (1, 1, 0); plane strain only.
      if (body.material.plane != PlaneHypothesis::Strain)
        throw std::invalid_argument("selective integration is implemented for plane strain only");
      Eigen::Matrix3d D_volumetric = Eigen::Matrix3d::Zero();
      D_volumetric.topLeftCorner<2, 2>().setConstant(body.material.lambda);
      const Eigen::Matrix3d D_rest = D - D_volumetric;
      add_cells<4>(body.mesh.quads, body.mesh, offset, D_volumetric,
                   [&](const Coords4& xy, const Eigen::Matrix3d& Dv) { return q1_stiffness_selective(xy, Dv, D_rest); },
                   triplets);
    } else if (body.mesh.element == ElementType::Q1) {
      add_cells<4>(body.mesh.quads, body.mesh, offset, D, q1_stiffness, triplets);
    } else {
      add_cells<3>(body.mesh.triangles, body.mesh, offset, D, p1_stiffness, triplets);
    }
  }
  SparseMatrix K(model.num_dofs(), model.num_dofs());
  K.setFromTriplets(triplets.begin(), triplets.end());
  return K;
}

Eigen::VectorXd assemble_tractions(const Model& model) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(model.num_dofs());
  for (const EdgeTraction& load : model.tractions) {
    const Mesh& mesh = model.bodies.at(load.body).mesh;
    const int offset = model.dof_offset(load.body);
    // Linear edges and a constant traction: each end node takes half the edge's resultant.
    for (const auto& [a, b] : load.edges) {
      const double length = (mesh.nodes.row(b) - mesh.nodes.row(a)).norm();
      for (int node : {a, b})
        for (int c = 0; c < 2; ++c) F[offset + 2 * node + c] += 0.5 * length * load.traction[c];
    }
  }
  for (const NodalForce& load : model.nodal_forces)
    for (int c = 0; c < 2; ++c) F[model.dof_offset(load.body) + 2 * load.node + c] += load.force[c];
  return F;
}

LinearSystem::LinearSystem(const Model& model)
    : K_full_(assemble_stiffness(model)), F_ext_(assemble_tractions(model)) {
  const int n = model.num_dofs();
  prescribed_.assign(n, 0.0);
  owner_.assign(n, "");
  for (const DirichletCondition& bc : model.dirichlet) {
    if (bc.component < 0 || bc.component > 1) throw std::invalid_argument("Dirichlet component must be 0 or 1");
    const int offset = model.dof_offset(bc.body);
    for (int node : bc.nodes) {
      const int dof = offset + 2 * node + bc.component;
      if (!owner_[dof].empty()) continue;
      owner_[dof] = bc.name;
      prescribed_[dof] = bc.value;
    }
  }
  free_index_.assign(n, -1);
  int num_free = 0;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b)
    for (int dof = model.dof_offset(b); dof < model.dof_offset(b + 1); ++dof)
      if (owner_[dof].empty()) {
        free_index_[dof] = num_free++;
        floating_free_.push_back(model.bodies[b].floating);
        body_free_.push_back(b);
      }
  for (const Body& body : model.bodies) body_names_.push_back(body.name);

  Triplets ff;
  F_f_ = Eigen::VectorXd::Zero(num_free);
  for (int dof = 0; dof < n; ++dof)
    if (free_index_[dof] >= 0) F_f_[free_index_[dof]] = F_ext_[dof];
  for (int col = 0; col < K_full_.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K_full_, col); it; ++it) {
      const int i = free_index_[it.row()], j = free_index_[it.col()];
      if (i >= 0 && j >= 0)
        ff.emplace_back(i, j, it.value());
      else if (i >= 0)
        F_f_[i] -= it.value() * prescribed_[it.col()];
    }
  K_ff_.resize(num_free, num_free);
  K_ff_.setFromTriplets(ff.begin(), ff.end());

  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const Body& body = model.bodies[b];
    if (!body.floating) continue;
    const std::optional<BandLayout> layout = band_layout(body.mesh);
    if (!layout) continue;
    FloatingBand band{b, *layout, column_stiffness(body.mesh, *layout, body.material, body.selective_integration), {}, {}};
    const int offset = model.dof_offset(b);
    Eigen::VectorXd nodal_load(2 * body.mesh.num_nodes());
    for (int dof = 0; dof < 2 * body.mesh.num_nodes(); ++dof) {
      band.free_dof.push_back(free_index_[offset + dof]);
      nodal_load[dof] = F_ext_[offset + dof];
    }
    // A floating body has no support, so all its DOFs are free and its load is its own.
    if (*std::min_element(band.free_dof.begin(), band.free_dof.end()) < 0) continue;
    band.F = column_forces(nodal_load, *layout);
    floating_bands_.push_back(std::move(band));
  }
}

Eigen::VectorXd LinearSystem::scatter(const Eigen::VectorXd& free_values) const {
  Eigen::VectorXd full = Eigen::VectorXd::Zero(num_dofs());
  for (int dof = 0; dof < num_dofs(); ++dof)
    if (free_index_[dof] >= 0) full[dof] = free_values[free_index_[dof]];
  return full;
}

Eigen::VectorXd LinearSystem::expand(const Eigen::VectorXd& u_free) const {
  Eigen::VectorXd u = scatter(u_free);
  for (int dof = 0; dof < num_dofs(); ++dof)
    if (free_index_[dof] < 0) u[dof] = prescribed_[dof];
  return u;
}

std::map<std::string, Eigen::Vector2d> LinearSystem::reactions(
    const Eigen::VectorXd& u_full, const Eigen::VectorXd& interface_force_full) const {
  // At a prescribed DOF the support supplies whatever the other forces leave unbalanced.
  const Eigen::VectorXd unbalanced = K_full_ * u_full - F_ext_ - interface_force_full;
  std::map<std::string, Eigen::Vector2d> result;
  for (int dof = 0; dof < num_dofs(); ++dof) {
    if (owner_[dof].empty()) continue;
    auto [it, inserted] = result.try_emplace(owner_[dof], Eigen::Vector2d::Zero());
    it->second[dof % 2] += unbalanced[dof];
  }
  return result;
}

}  // namespace thinlayer
