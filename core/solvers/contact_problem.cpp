#include "core/solvers/contact_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/fem/column_basis.h"

namespace thinlayer {

namespace {

// Stiffness of one node of one body against a unit displacement along e, from the diagonal
// 2×2 block of the free stiffness matrix.
double nodal_stiffness(const LinearSystem& system, int global_dof_x, const Eigen::Vector2d& e) {
  const int ix = system.free_index(global_dof_x), iy = system.free_index(global_dof_x + 1);
  if (ix < 0 || iy < 0)
    throw std::runtime_error("interface node with a prescribed displacement component is not supported");
  const auto& K = system.K();
  return e.x() * e.x() * K.coeff(ix, ix) + 2 * e.x() * e.y() * K.coeff(ix, iy) + e.y() * e.y() * K.coeff(iy, iy);
}

double clamp_abs(double value, double bound) { return std::clamp(value, -bound, bound); }

}  // namespace

ContactProblem::ContactProblem(const LinearSystem& system, std::vector<Interface> interfaces)
    : system_(&system), interfaces_(std::move(interfaces)) {
  for (int i = 0; i < static_cast<int>(interfaces_.size()); ++i)
    for (const InterfaceNode& n : interfaces_[i].nodes) {
      nodes_.push_back(n);
      interface_of_.push_back(i);
    }
  const int m = num_nodes();
  g_D_ = Eigen::VectorXd::Zero(2 * m);
  C_ = Eigen::VectorXd::Zero(2 * m);
  kappa_ = Eigen::VectorXd::Zero(2 * m);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < m; ++k) {
    const InterfaceNode& n = nodes_[k];
    const InterfaceLaw& law = this->law(k);
    const Eigen::Vector2d e[2] = {n.normal, n.tangent()};
    // [u]_N = n·(u⁻ - u⁺), [u]_T = t·(u⁺ - u⁻): the plus side enters with -n and +t.
    const double plus_sign[2] = {-1, +1};
    for (int row = 0; row < 2; ++row) {
      auto add_side = [&](int dof_x, double sign) {
        for (int c = 0; c < 2; ++c) {
          const double coef = sign * plus_sign[row] * e[row][c];
          const int free = system.free_index(dof_x + c);
          if (free >= 0)
            triplets.emplace_back(2 * k + row, free, coef);
          else
            g_D_[2 * k + row] += coef * system.prescribed_value(dof_x + c);
        }
      };
      add_side(n.plus_dof_x, +1);
      if (!n.on_foundation()) add_side(n.minus_dof_x, -1);

      C_[2 * k + row] = (row == 0 ? law.compliance_N() : law.compliance_T()) / n.length;
      double flexibility = 1.0 / nodal_stiffness(system, n.plus_dof_x, e[row]);
      if (!n.on_foundation()) flexibility += 1.0 / nodal_stiffness(system, n.minus_dof_x, e[row]);
      if (std::isfinite(C_[2 * k + row])) flexibility += C_[2 * k + row];
      kappa_[2 * k + row] = 1.0 / flexibility;
    }
  }
  B_.resize(2 * m, system.num_free());
  B_.setFromTriplets(triplets.begin(), triplets.end());
}

Eigen::Vector2d natural_map(const InterfaceLaw& law, const Eigen::Vector2d& r, const Eigen::Vector2d& d,
                            const Eigen::Vector2d& kappa) {
  Eigen::Vector2d R;
  if (law.bilateral) {  // d = 0 on each row that carries a force, whatever the sign of r (SPEC §1.6)
    R[0] = law.normal_active() ? kappa[0] * d[0] : r[0];
    R[1] = law.K_T() > 0 ? kappa[1] * d[1] : r[1];
    return R;
  }
  const double p = -r[0];  // contact pressure force, ≥ 0 in compression
  R[0] = law.normal_active() ? p - std::max(0.0, p + kappa[0] * d[0]) : r[0];
  const double threshold = law.tangential_active() ? law.friction * std::max(p, 0.0) : 0.0;
  R[1] = law.K_T() > 0 ? r[1] - clamp_abs(r[1] - kappa[1] * d[1], threshold) : r[1];
  return R;
}

double Residual::floor() const {
  return per_body_floor.empty() ? 0.0 : *std::max_element(per_body_floor.begin(), per_body_floor.end());
}

namespace {

// A band's imbalance and its round-off bound, evaluated in its column basis and written over the
// nodal ones at its free DOFs.
void band_imbalance(const FloatingBand& band, const Eigen::VectorXd& z, const Eigen::VectorXd& interface_force,
                    const Eigen::VectorXd& interface_force_bound, Eigen::VectorXd& imbalance,
                    Eigen::VectorXd& magnitude) {
  const int n = static_cast<int>(band.free_dof.size());
  Eigen::VectorXd contact(n), contact_bound(n);
  for (int k = 0; k < n; ++k) {
    contact[k] = interface_force[band.free_dof[k]];
    contact_bound[k] = interface_force_bound[band.free_dof[k]];
  }
  const Eigen::VectorXd column = band.K * z - band.F - column_forces(contact, band.layout);
  const Eigen::VectorXd column_bound = band.K.cwiseAbs() * z.cwiseAbs() + band.F.cwiseAbs() +
                                       column_forces(contact_bound, band.layout);
  const Eigen::VectorXd nodal = nodal_forces(column, band.layout);
  const Eigen::VectorXd nodal_bound = nodal_force_bound(column_bound, band.layout);
  for (int k = 0; k < n; ++k) {
    imbalance[band.free_dof[k]] = nodal[k];
    magnitude[band.free_dof[k]] = nodal_bound[k];
  }
}

}  // namespace

Residual contact_residual(const ContactProblem& problem, const Eigen::VectorXd& u_free,
                          const Eigen::VectorXd& r, const std::vector<Eigen::VectorXd>& band_z) {
  const LinearSystem& system = problem.system();
  const double floor = residual_load_floor * system.F().norm();
  auto relative = [floor](double norm2, double scale2) {
    const double scale = std::max(std::sqrt(scale2), floor);
    return scale > 0 ? std::sqrt(norm2) / scale : std::sqrt(norm2);
  };
  Residual res;

  // Bulk, body by body: the imbalance and the forces on each body's own DOFs.
  const Eigen::VectorXd interface_force = problem.B().transpose() * r;
  Eigen::VectorXd imbalance = system.K() * u_free - system.F() - interface_force;
  const Eigen::VectorXd interface_force_bound = problem.B().cwiseAbs().transpose() * r.cwiseAbs();
  const Eigen::VectorXd nodal_magnitude =
      system.K().cwiseAbs() * u_free.cwiseAbs() + system.F().cwiseAbs() + interface_force_bound;
  Eigen::VectorXd magnitude = nodal_magnitude;
  if (!band_z.empty()) {
    const std::vector<FloatingBand>& bands = system.floating_bands();
    if (band_z.size() != bands.size())
      throw std::invalid_argument("contact_residual: " + std::to_string(band_z.size()) + " band displacements for " +
                                  std::to_string(bands.size()) + " layer bands");
    for (size_t k = 0; k < bands.size(); ++k)
      band_imbalance(bands[k], band_z[k], interface_force, interface_force_bound, imbalance, magnitude);
  }
  const int bodies = system.num_bodies();
  std::vector<double> imbalance2(bodies, 0.0), load2(bodies, 0.0), contact2(bodies, 0.0), magnitude2(bodies, 0.0),
      nodal_magnitude2(bodies, 0.0);
  for (int i = 0; i < system.num_free(); ++i) {
    const int b = system.body_of(i);
    imbalance2[b] += imbalance[i] * imbalance[i];
    load2[b] += system.F()[i] * system.F()[i];
    contact2[b] += interface_force[i] * interface_force[i];
    magnitude2[b] += magnitude[i] * magnitude[i];
    nodal_magnitude2[b] += nodal_magnitude[i] * nodal_magnitude[i];
  }
  constexpr double unit_roundoff = 0.5 * std::numeric_limits<double>::epsilon();
  for (int b = 0; b < bodies; ++b) {
    res.per_body.push_back(relative(imbalance2[b], std::max(load2[b], contact2[b])));
    res.per_body_floor.push_back(unit_roundoff * relative(magnitude2[b], std::max(load2[b], contact2[b])));
    res.per_body_nodal_floor.push_back(unit_roundoff * relative(nodal_magnitude2[b], std::max(load2[b], contact2[b])));
    res.bulk = std::max(res.bulk, res.per_body.back());
  }

  // Interfaces, one by one: the natural map against the forces that interface carries.
  const Eigen::VectorXd g = problem.jumps(u_free);
  const int interfaces = static_cast<int>(problem.interfaces().size());
  std::vector<double> map2(interfaces, 0.0), force2(interfaces, 0.0);
  for (int k = 0; k < problem.num_nodes(); ++k) {
    Eigen::Vector2d d;
    for (int row = 0; row < 2; ++row) {
      const double c = problem.compliance()[2 * k + row];
      d[row] = g[2 * k + row] + (std::isfinite(c) ? c * r[2 * k + row] : 0.0);
    }
    const Eigen::Vector2d R = natural_map(problem.law(k), r.segment<2>(2 * k), d, problem.kappa().segment<2>(2 * k));
    map2[problem.interface_of(k)] += R.squaredNorm();
    force2[problem.interface_of(k)] += r.segment<2>(2 * k).squaredNorm();
  }
  for (int i = 0; i < interfaces; ++i) {
    res.per_interface.push_back(relative(map2[i], force2[i]));
    res.interface = std::max(res.interface, res.per_interface.back());
  }
  return res;
}

std::vector<NodeStatus> classify_statuses(const std::vector<InterfaceLaw>& laws,
                                          const Eigen::VectorXd& sigma_N,
                                          const Eigen::VectorXd& sigma_T, double tolerance) {
  // The scale: the largest |σ_N|, and at a bilateral node the largest |σ_T| too (a bonded joint
  // in pure shear carries its load without any σ_N).
  double scale = 0;
  for (int k = 0; k < sigma_N.size(); ++k) {
    scale = std::max(scale, std::abs(sigma_N[k]));
    if (laws[k].bilateral) scale = std::max(scale, std::abs(sigma_T[k]));
  }
  std::vector<NodeStatus> status(sigma_N.size());
  for (int k = 0; k < sigma_N.size(); ++k) {
    if (laws[k].bilateral) {
      // A bonded node never opens nor slides: "stick" while it carries a stress (tension too,
      // which is not a gap), "gap" where it carries none.
      const bool loaded = std::max(std::abs(sigma_N[k]), std::abs(sigma_T[k])) > tolerance * scale;
      status[k] = loaded ? NodeStatus::Stick : NodeStatus::Gap;
      continue;
    }
    const double pressure = -sigma_N[k];
    if (!(pressure > tolerance * scale)) {
      status[k] = NodeStatus::Gap;
      continue;
    }
    const double threshold = laws[k].friction * pressure;
    status[k] = std::abs(sigma_T[k]) >= (1 - tolerance) * threshold ? NodeStatus::Slide : NodeStatus::Stick;
  }
  return status;
}

NodeStatus combined_status(NodeStatus plus_face, NodeStatus minus_face) {
  if (plus_face == NodeStatus::Gap || minus_face == NodeStatus::Gap) return NodeStatus::Gap;
  if (plus_face == NodeStatus::Slide || minus_face == NodeStatus::Slide) return NodeStatus::Slide;
  return NodeStatus::Stick;
}

StatusCount count_statuses(const std::vector<NodeStatus>& statuses) {
  StatusCount c;
  for (NodeStatus s : statuses) {
    if (s == NodeStatus::Gap) ++c.gap;
    else if (s == NodeStatus::Slide) ++c.slide;
    else ++c.stick;
  }
  return c;
}

}  // namespace thinlayer
