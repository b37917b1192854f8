#include "core/solvers/relaxation_solver.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace thinlayer {

namespace {

// One interface unknown: which node, and whether it is the normal or tangential component.
struct InterfaceUnknown {
  int node = -1;
  bool normal = false;
};

// Change of unknowns u = T v that puts interface nodes in their local frame: for a node on a
// foundation, v = (t·u⁺, n·u⁺); for a pair, the minus node in the local frame and the plus
// node relative to it, v = (t·(u⁺-u⁻), n·(u⁺-u⁻)). Then [u]_T = v_t and [u]_N = -v_n.
struct LocalFrame {
  Eigen::SparseMatrix<double> T;
  std::vector<InterfaceUnknown> unknown;  // per free DOF
};

LocalFrame local_frame(const ContactProblem& problem) {
  const LinearSystem& system = problem.system();
  const int n = system.num_free();
  LocalFrame frame;
  frame.unknown.assign(n, {});
  std::vector<int> frame_of(n, -1);  // interface node whose frame a free DOF belongs to
  auto claim = [&](int dof_x, int k) {
    for (int c = 0; c < 2; ++c) {
      const int i = system.free_index(dof_x + c);
      if (i < 0) throw std::runtime_error("relaxation: interface node with a prescribed DOF");
      if (frame_of[i] >= 0) throw std::runtime_error("relaxation: a node belongs to two interface pairs");
      frame_of[i] = k;
    }
  };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceNode& node = problem.node(k);
    claim(node.plus_dof_x, k);
    if (!node.on_foundation()) claim(node.minus_dof_x, k);
  }
  for (int i = 0; i < n; ++i)
    if (frame_of[i] < 0) t.emplace_back(i, i, 1.0);
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceNode& node = problem.node(k);
    const Eigen::Vector2d nn = node.normal, tt = node.tangent();
    const int px = system.free_index(node.plus_dof_x);  // v_t at px, v_n at px + 1
    // u⁺ = t v_t + n v_n (+ u⁻ for a pair)
    for (int c = 0; c < 2; ++c) {
      t.emplace_back(px + c, px, tt[c]);
      t.emplace_back(px + c, px + 1, nn[c]);
    }
    frame.unknown[px] = {k, false};
    frame.unknown[px + 1] = {k, true};
    if (!node.on_foundation()) {
      const int mx = system.free_index(node.minus_dof_x);  // minus node: a_t at mx, a_n at mx + 1
      for (int c = 0; c < 2; ++c)
        for (int row : {mx + c, px + c}) {  // u⁻ = t a_t + n a_n, and u⁺ contains u⁻
          t.emplace_back(row, mx, tt[c]);
          t.emplace_back(row, mx + 1, nn[c]);
        }
    }
  }
  frame.T.resize(n, n);
  frame.T.setFromTriplets(t.begin(), t.end());
  return frame;
}

// Exact minimisation along one interface unknown of ½ a v² - b v + (interface energy):
// the paper's switches, each evaluated consistently at the new value.
double update_normal(double a, double b, double k_N) {
  // γ = 0: no penetration ([u]_N = -v ≤ 0); γ = 1: the spring K_N ℓ acts. For K_N = ∞ the
  // second branch gives v = 0, i.e. the projection onto the Signorini constraint.
  return b >= 0 ? b / a : b / (a + k_N);
}

double update_tangential(double a, double b, double k_T, double rho) {
  // η = 1: the spring alone, valid while its force stays below ρ.
  const double spring_force = std::isinf(k_T) ? b : k_T * b / (a + k_T);
  if (std::abs(spring_force) <= rho) return std::isinf(k_T) ? 0.0 : b / (a + k_T);
  // θ = ±1: the slider carries the constant force ρ.
  return (b - std::copysign(rho, b)) / a;
}

}  // namespace

SolveReport solve_relaxation(const ContactProblem& problem, const SolverOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  report.solver = "relaxation";
  report.tolerance = options.tolerance;
  const int max_sweeps = options.max_iterations > 0 ? options.max_iterations : 100000;
  const double omega = options.omega;
  if (!(omega > 0 && omega < 2)) throw std::invalid_argument("relaxation: omega must be in (0, 2)");
  for (int k = 0; k < problem.num_nodes(); ++k)  // the paper's algorithm knows Signorini-Coulomb only
    if (problem.law(k).bilateral)
      throw std::invalid_argument("the relaxation solver (the paper's algorithm) has no bonded faces (interface '" +
                                  problem.interfaces()[problem.interface_of(k)].name + "'): use the fast solver");

  const LinearSystem& system = problem.system();
  const LocalFrame frame = local_frame(problem);
  const Eigen::SparseMatrix<double, Eigen::RowMajor> K = frame.T.transpose() * system.K() * frame.T;
  const Eigen::VectorXd F = frame.T.transpose() * system.F();
  const int n = static_cast<int>(F.size());
  const int m = problem.num_nodes();

  // Nodal stiffnesses K ℓ (daN/mm), +∞ for a rigid law, and friction thresholds ρ (daN).
  std::vector<double> k_N(m), k_T(m), rho(m, 0.0);
  for (int k = 0; k < m; ++k) {
    k_N[k] = problem.law(k).K_N() * problem.node(k).length;
    k_T[k] = problem.law(k).tangential_active() ? problem.law(k).K_T() * problem.node(k).length : 0.0;
  }
  Eigen::VectorXd diag(n);
  for (int i = 0; i < n; ++i) {
    diag[i] = K.coeff(i, i);
    // Gauss-Seidel divides by the diagonal: a DOF without stiffness makes the system singular.
    if (!(diag[i] > 0) || !std::isfinite(diag[i]))
      throw std::runtime_error("singular system: free DOF " + std::to_string(i) + " has diagonal stiffness " +
                               std::to_string(diag[i]) + " (a body without stiffness?)");
  }

  Eigen::VectorXd v = Eigen::VectorXd::Zero(n);
  // Interface forces from the current iterate: at an interface unknown the interface term
  // balances the bulk, r_N = -(K v - F)_n and r_T = (K v - F)_t.
  auto interface_forces = [&]() {
    Eigen::VectorXd r(2 * m);
    for (int i = 0; i < n; ++i) {
      const InterfaceUnknown& iu = frame.unknown[i];
      if (iu.node < 0) continue;
      const double unbalanced = K.row(i).dot(v) - F[i];
      r[2 * iu.node + (iu.normal ? 0 : 1)] = iu.normal ? -unbalanced : unbalanced;
    }
    return r;
  };
  auto update_rho = [&](const Eigen::VectorXd& r) {
    for (int k = 0; k < m; ++k) rho[k] = problem.law(k).friction * std::max(0.0, -r[2 * k]);
  };

  const int check_every = std::max(1, options.sweeps_per_rho_update);
  report.converged = false;
  int sweep = 0;
  while (sweep < max_sweeps) {
    for (int i = 0; i < n; ++i) {
      double b = F[i];
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(K, i); it; ++it)
        if (it.col() != i) b -= it.value() * v[it.col()];
      const InterfaceUnknown& iu = frame.unknown[i];
      double half = b / diag[i];
      if (iu.node >= 0)
        half = iu.normal ? update_normal(diag[i], b, k_N[iu.node])
                         : update_tangential(diag[i], b, k_T[iu.node], rho[iu.node]);
      double next = (1 - omega) * v[i] + omega * half;
      // Over-relaxation may step through the Signorini constraint: project back onto it.
      if (iu.node >= 0 && iu.normal && std::isinf(k_N[iu.node])) next = std::max(next, 0.0);
      v[i] = next;
    }
    ++sweep;
    if (sweep % check_every == 0 || sweep == max_sweeps) {
      const Eigen::VectorXd r = interface_forces();
      update_rho(r);  // the fixed point on the friction threshold (diagonal procedure)
      report.residual = contact_residual(problem, frame.T * v, r);
      if (options.verbose && sweep % (100 * check_every) == 0)
        std::cerr << "relaxation: sweep " << sweep << ", residual " << report.residual.value() << "\n";
      if (report.residual.value() <= options.tolerance) {
        report.converged = true;
        break;
      }
      if (!std::isfinite(report.residual.value())) break;  // NaN or Inf: no sweep will recover
    }
  }
  report.iterations = sweep;
  report.u = frame.T * v;
  report.r = interface_forces();
  report.residual = contact_residual(problem, report.u, report.r);
  report.converged = report.residual.value() <= options.tolerance;
  const bool finite = report.u.allFinite() && report.r.allFinite() && std::isfinite(report.residual.value());
  report.stop_cause = !finite ? StopCause::NonFinite : report.converged ? StopCause::Converged : StopCause::IterationCap;
  report.converged = report.stop_cause == StopCause::Converged;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (report.converged ? "converged" : std::string("NOT converged (") + to_string(report.stop_cause) + ")")
      << " after " << sweep
      << " sweeps (omega " << omega << ", rho updated every " << check_every << " sweeps), residual "
      << report.residual.value() << " (tolerance " << options.tolerance << ")";
  report.message = msg.str();
  return report;
}

}  // namespace thinlayer
