#include "core/solvers/contact_problem.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/fem/column_basis.h"
#include "core/linalg/extended_products.h"

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

}  // namespace

Eigen::VectorXd ContactProblem::stop_jumps(const Eigen::VectorXd& u_free, const Eigen::VectorXd& r) const {
  Eigen::VectorXd d = jumps(u_free);
  for (int i = 0; i < d.size(); ++i)
    if (std::isfinite(C_[i])) d[i] += C_[i] * r[i];
  return d;
}

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

namespace {

// The natural map of one node in any precision (the residual evaluates it in long double).
template <typename Scalar>
Eigen::Matrix<Scalar, 2, 1> natural_map_in(const InterfaceLaw& law, const Eigen::Matrix<Scalar, 2, 1>& r,
                                           const Eigen::Matrix<Scalar, 2, 1>& d, const Eigen::Vector2d& kappa) {
  Eigen::Matrix<Scalar, 2, 1> R;
  if (law.bilateral) {  // d = 0 on each row that carries a force, whatever the sign of r (SPEC §1.6)
    R[0] = law.normal_active() ? Scalar(kappa[0]) * d[0] : r[0];
    R[1] = law.K_T() > 0 ? Scalar(kappa[1]) * d[1] : r[1];
    return R;
  }
  const Scalar p = -r[0];  // contact pressure force, ≥ 0 in compression
  R[0] = law.normal_active() ? p - std::max(Scalar(0), p + Scalar(kappa[0]) * d[0]) : r[0];
  const Scalar threshold = law.tangential_active() ? Scalar(law.friction) * std::max(p, Scalar(0)) : Scalar(0);
  R[1] = law.K_T() > 0 ? r[1] - std::clamp(r[1] - Scalar(kappa[1]) * d[1], -threshold, threshold) : r[1];
  return R;
}

}  // namespace

Eigen::Vector2d natural_map(const InterfaceLaw& law, const Eigen::Vector2d& r, const Eigen::Vector2d& d,
                            const Eigen::Vector2d& kappa) {
  return natural_map_in<double>(law, r, d, kappa);
}

double Residual::floor() const {
  double f = 0;
  for (double v : per_body_floor) f = std::max(f, v);
  for (double v : per_interface_floor) f = std::max(f, v);
  return f;
}

namespace {

// A band's imbalance (extended precision) and its round-off bound, evaluated in its column basis
// and written over the nodal ones at its free DOFs.
void band_imbalance(const FloatingBand& band, const Eigen::VectorXd& z, const LongVector& interface_force,
                    const Eigen::VectorXd& interface_force_bound, LongVector& imbalance, Eigen::VectorXd& magnitude) {
  const int n = static_cast<int>(band.free_dof.size());
  LongVector contact(n);
  Eigen::VectorXd contact_bound(n);
  for (int k = 0; k < n; ++k) {
    contact[k] = interface_force[band.free_dof[k]];
    contact_bound[k] = interface_force_bound[band.free_dof[k]];
  }
  const LongVector column = times(band.K, z) - band.F.cast<Long>() - column_forces(contact, band.layout);
  const Eigen::VectorXd column_bound = band.K.cwiseAbs() * z.cwiseAbs() + band.F.cwiseAbs() +
                                       column_forces(contact_bound, band.layout);
  const LongVector nodal = nodal_forces(column, band.layout);
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
  auto relative = [floor](Long norm2, Long scale2) {
    const double scale = std::max(double(std::sqrt(scale2)), floor);
    return scale > 0 ? double(std::sqrt(norm2)) / scale : double(std::sqrt(norm2));
  };
  constexpr double unit_roundoff = 0.5 * std::numeric_limits<double>::epsilon();
  Residual res;

  // Bulk, body by body: the imbalance and the forces on each body's own DOFs, evaluated in
  // extended precision (SPEC §1.5: what is left is the answer's, not the evaluation's).
  const LongVector interface_force = transpose_times(problem.B(), r);
  LongVector imbalance = times(system.K(), u_free) - system.F().cast<Long>() - interface_force;
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
  std::vector<Long> imbalance2(bodies, 0), load2(bodies, 0), contact2(bodies, 0), magnitude2(bodies, 0),
      nodal_magnitude2(bodies, 0);
  for (int i = 0; i < system.num_free(); ++i) {
    const int b = system.body_of(i);
    imbalance2[b] += imbalance[i] * imbalance[i];
    load2[b] += Long(system.F()[i]) * system.F()[i];
    contact2[b] += interface_force[i] * interface_force[i];
    magnitude2[b] += Long(magnitude[i]) * magnitude[i];
    nodal_magnitude2[b] += Long(nodal_magnitude[i]) * nodal_magnitude[i];
  }
  for (int b = 0; b < bodies; ++b) {
    res.per_body.push_back(relative(imbalance2[b], std::max(load2[b], contact2[b])));
    res.per_body_floor.push_back(unit_roundoff * relative(magnitude2[b], std::max(load2[b], contact2[b])));
    res.per_body_nodal_floor.push_back(unit_roundoff * relative(nodal_magnitude2[b], std::max(load2[b], contact2[b])));
    res.bulk = std::max(res.bulk, res.per_body.back());
  }

  // Interfaces, one by one: the natural map against the forces that interface carries, in
  // extended precision too; its floor is what rounding u and r to double moves it by,
  // u_eps (|r| + κ (|B||u| + |g_D| + |C r|)) per row.
  const LongVector g = times(problem.B(), u_free) + problem.jump_offset().cast<Long>();
  const Eigen::VectorXd g_bound = problem.B().cwiseAbs() * u_free.cwiseAbs() + problem.jump_offset().cwiseAbs();
  const int interfaces = static_cast<int>(problem.interfaces().size());
  std::vector<Long> map2(interfaces, 0), force2(interfaces, 0), bound2(interfaces, 0);
  for (int k = 0; k < problem.num_nodes(); ++k) {
    Eigen::Matrix<Long, 2, 1> d, rk;
    for (int row = 0; row < 2; ++row) {
      const double c = problem.compliance()[2 * k + row];
      rk[row] = r[2 * k + row];
      d[row] = g[2 * k + row] + (std::isfinite(c) ? Long(c) * rk[row] : Long(0));
      const double kappa = problem.kappa()[2 * k + row];
      const double row_bound = std::abs(r[2 * k + row]) +
          kappa * (g_bound[2 * k + row] + (std::isfinite(c) ? c * std::abs(r[2 * k + row]) : 0.0));
      bound2[problem.interface_of(k)] += Long(row_bound) * row_bound;
    }
    const Eigen::Matrix<Long, 2, 1> R = natural_map_in<Long>(problem.law(k), rk, d, problem.kappa().segment<2>(2 * k));
    map2[problem.interface_of(k)] += R.squaredNorm();
    force2[problem.interface_of(k)] += rk.squaredNorm();
  }
  for (int i = 0; i < interfaces; ++i) {
    res.per_interface.push_back(relative(map2[i], force2[i]));
    res.per_interface_floor.push_back(unit_roundoff * relative(bound2[i], force2[i]));
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

// The adherents' median nodal stiffness along the interfaces: the scale of the layer solvers' springs.
double adherent_stiffness(const ContactProblem& problem) {
  const LinearSystem& system = problem.system();
  std::vector<double> k;
  for (int n = 0; n < problem.num_nodes(); ++n)
    for (int dof : {problem.node(n).plus_dof_x, problem.node(n).minus_dof_x}) {
      if (dof < 0) continue;
      const int free = system.free_index(dof);
      if (free >= 0 && !system.floating(free)) k.push_back(system.K().coeff(free, free));
    }
  if (k.empty()) {  // only floating bodies touch the interfaces: their own stiffness
    for (int i = 0; i < system.num_free(); ++i) k.push_back(system.K().coeff(i, i));
  }
  std::nth_element(k.begin(), k.begin() + k.size() / 2, k.end());
  return k[k.size() / 2];
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
