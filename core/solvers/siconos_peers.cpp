#include "core/solvers/siconos_peers.h"

#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

// Siconos numerics is C; its SolverOptions is the global ::SolverOptions, not ours.
#include <FrictionContactProblem.h>
#include <Friction_cst.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <NumericsVerbose.h>
#include <SolverOptions.h>

namespace thinlayer {

namespace {

// The Siconos objects we allocate, released however the solve ends.
struct MatrixDeleter {
  void operator()(NumericsMatrix* m) const { NM_free(m); }  // frees the dense data and the struct
};
struct OptionsDeleter {
  void operator()(::SolverOptions* o) const {
    solver_options_delete(o);  // its arrays and internal solvers (Siconos 4.4 leaves the struct)
    free(o);                   // NOLINT: malloc'ed by solver_options_create
  }
};

// Our law and Siconos' 2D Coulomb problem, row by row (SPEC §1.2 and core/interface/law.h):
//
//   ours:     d = g₀ + (W + C) r;   r_N ≤ 0, d_N ≤ 0, r_N d_N = 0 ([u]_N > 0 is interpenetration,
//             compression is negative);   |r_T| ≤ f |r_N|, d_T = -ζ r_T, ζ ≥ 0.
//   Siconos:  u = M ρ + q;          ρ_N ≥ 0, u_N ≥ 0, ρ_N u_N = 0;   |ρ_T| ≤ μ ρ_N, and on a slide
//             ρ_T = +μ ρ_N with u_T ≤ 0 or ρ_T = -μ ρ_N with u_T ≥ 0 (the force opposes the slip).
//
// With ρ = S r, u = S d, S = diag(s_N, s_T) per node: M = S (W + C) S, q = S g₀. The normal needs
// s_N = -1 (both sign conventions flip). The tangential law only says that force and slip have
// opposite signs, which either s_T keeps; we take s_T = +1. Checked on the bar's Table 3 row 1
// (14 slides): s_T = -1 gives the same forces to 1e-11 with Lemke, while s_N = +1 returns r = 0
// (the foundation seen as pulling). Units are unchanged: ρ in daN per unit thickness, u in mm,
// M in mm/daN. A finite compliance C = 1/(K ℓ) is the layer's spring in series with the
// stop and the skidding block, which is exactly a diagonal added to the Delassus operator.
constexpr double s_N = -1.0, s_T = +1.0;

struct MappedProblem {
  std::vector<int> nodes;   // our node index of each Siconos contact
  Eigen::MatrixXd M;        // 2 nc × 2 nc, column-major as Siconos' dense storage
  std::vector<double> q, mu;
};

MappedProblem map_problem(const ContactProblem& problem, const CondensedInterface& condensed) {
  MappedProblem p;
  // A node without normal interaction (K_N = 0) carries no force at all (r_N = 0, hence r_T = 0):
  // it is left out. A node with normal but no tangential interaction (K_T = 0 or f = 0) is a
  // frictionless contact, μ = 0; its T row is kept (Siconos' contacts are 2D) and the cone
  // holds ρ_T = 0, so an infinite tangential compliance is simply not added.
  for (int k = 0; k < problem.num_nodes(); ++k)
    if (problem.law(k).normal_active()) p.nodes.push_back(k);
  const int nc = static_cast<int>(p.nodes.size());
  const double s[2] = {s_N, s_T};
  const Eigen::MatrixXd& W = condensed.W();
  const Eigen::VectorXd& C = problem.compliance();
  p.M.resize(2 * nc, 2 * nc);
  p.q.resize(2 * nc);
  p.mu.resize(nc);
  for (int a = 0; a < nc; ++a) {
    const InterfaceLaw& law = problem.law(p.nodes[a]);
    p.mu[a] = law.tangential_active() ? law.friction : 0.0;
    for (int i = 0; i < 2; ++i) {
      const int row = 2 * p.nodes[a] + i;
      p.q[2 * a + i] = s[i] * condensed.g0()[row];
      for (int b = 0; b < nc; ++b)
        for (int j = 0; j < 2; ++j) p.M(2 * a + i, 2 * b + j) = s[i] * s[j] * W(row, 2 * p.nodes[b] + j);
      if (std::isfinite(C[row])) p.M(2 * a + i, 2 * a + i) += C[row];  // s_i² = 1
    }
  }
  return p;
}

// At most this many NSGS sweeps or Lemke pivots: options.max_iterations, else 1e5 sweeps or
// Siconos' own default of 1e4 pivots.
int iteration_cap(PeerSolver solver, const SolverOptions& options) {
  if (options.max_iterations > 0) return options.max_iterations;
  return solver == PeerSolver::NSGS ? 100000 : 10000;
}

struct PeerRun {
  int info = 0;          // the driver's return code (0: the peer says it converged)
  int iterations = 0;    // iparam[SICONOS_IPARAM_ITER_DONE]: NSGS sweeps, Lemke pivots
  double error = 0;      // dparam[SICONOS_DPARAM_RESIDU]: the peer's own error measure
  std::vector<double> reaction;
};

PeerRun run_peer(MappedProblem& p, PeerSolver solver, const SolverOptions& options) {
  const int nc = static_cast<int>(p.nodes.size()), n = 2 * nc;
  std::unique_ptr<NumericsMatrix, MatrixDeleter> M(NM_create(NM_DENSE, n, n));
  std::copy(p.M.data(), p.M.data() + p.M.size(), M->matrix0);
  // The problem struct only points at data owned here (M above, q and mu in p).
  FrictionContactProblem fc{};
  fc.dimension = 2;
  fc.numberOfContacts = nc;
  fc.M = M.get();
  fc.q = p.q.data();
  fc.mu = p.mu.data();

  const int id = solver == PeerSolver::NSGS ? SICONOS_FRICTION_2D_NSGS : SICONOS_FRICTION_2D_LEMKE;
  std::unique_ptr<::SolverOptions, OptionsDeleter> so(solver_options_create(id));
  if (!so) throw std::runtime_error("Siconos could not create the solver options");
  so->iparam[SICONOS_IPARAM_MAX_ITER] = iteration_cap(solver, options);
  so->dparam[SICONOS_DPARAM_TOL] = options.tolerance;
  numerics_set_verbose(0);  // Siconos prints to stdout when verbose

  PeerRun run;
  run.reaction.assign(n, 0.0);
  std::vector<double> velocity(n, 0.0);
  // With a dense M, fc2d_driver dispatches NSGS to fc2d_nsgs_dense and Lemke to fc2d_lexicolemke.
  run.info = fc2d_driver(&fc, run.reaction.data(), velocity.data(), so.get());
  run.iterations = so->iparam[SICONOS_IPARAM_ITER_DONE];
  run.error = so->dparam[SICONOS_DPARAM_RESIDU];
  return run;
}

}  // namespace

const char* to_string(PeerSolver solver) { return solver == PeerSolver::NSGS ? "siconos-nsgs" : "siconos-lemke"; }

SolveReport solve_siconos(const ContactProblem& problem, const CondensedInterface& condensed, PeerSolver solver,
                          const SolverOptions& options) {
  if (condensed.num_floating_unknowns() > 0)
    throw std::invalid_argument(std::string(to_string(solver)) +
                                ": scenes with a floating body (thin-layer mode) are not supported");
  for (int k = 0; k < problem.num_nodes(); ++k)  // Siconos' 2D Coulomb problem is unilateral
    if (problem.law(k).bilateral)
      throw std::invalid_argument(std::string(to_string(solver)) + ": bonded faces (a bilateral law) are not supported");
  // Timed like solve_fast: the mapping, the peer's solve, and the displacement and residual.
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  report.solver = to_string(solver);
  report.tolerance = options.tolerance;

  MappedProblem p = map_problem(problem, condensed);
  report.r = Eigen::VectorXd::Zero(2 * problem.num_nodes());
  PeerRun run;
  if (!p.nodes.empty()) {
    run = run_peer(p, solver, options);
    for (size_t a = 0; a < p.nodes.size(); ++a) {  // back to our signs: r = S ρ (S = S⁻¹)
      report.r[2 * p.nodes[a]] = s_N * run.reaction[2 * a];
      report.r[2 * p.nodes[a] + 1] = s_T * run.reaction[2 * a + 1];
    }
  }
  report.iterations = run.iterations;
  report.u = condensed.displacement(problem, report.r, Eigen::VectorXd());
  report.residual = contact_residual(problem, report.u, report.r);
  report.converged = report.residual.value() <= options.tolerance;
  // Why a peer stopped short: its cap, or its own criterion met above our residual.
  report.stop_cause = !report.u.allFinite() || !std::isfinite(report.residual.value()) ? StopCause::NonFinite
                      : report.converged                                      ? StopCause::Converged
                      : run.iterations >= iteration_cap(solver, options)      ? StopCause::IterationCap
                                                                              : StopCause::LossOfAccuracy;
  report.converged = report.stop_cause == StopCause::Converged;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::ostringstream msg;
  msg << (report.converged ? "converged" : "NOT converged") << ": "
      << (solver == PeerSolver::NSGS ? "fc2d_nsgs_dense" : "fc2d_lexicolemke");
  if (p.nodes.empty())
    msg << " not called (no node with a normal interaction: r = 0)";
  else
    msg << " info " << run.info << ", its own error " << run.error << " after " << run.iterations
        << (solver == PeerSolver::NSGS ? " sweeps" : " pivots");
  msg << ", residual " << report.residual.value() << " (tolerance " << options.tolerance << ")";
  report.message = msg.str();
  return report;
}

}  // namespace thinlayer
