#include "core/solvers/sparse_newton.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>

#include "core/solvers/bonded_solve.h"
#include "core/solvers/mixed_system.h"

namespace thinlayer {

bool takes_sparse_newton(const ContactProblem& problem) {
  const LinearSystem& system = problem.system();
  if (every_interface_bonded(problem) || !system.floating_bands().empty()) return false;
  for (int i = 0; i < system.num_free(); ++i)
    if (system.floating(i)) return true;
  return false;
}

std::vector<Active> stuck_statuses(const ContactProblem& problem) {
  std::vector<Active> statuses(problem.num_nodes());
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceLaw& law = problem.law(k);
    if (law.bilateral) statuses[k] = law.normal_active() || law.K_T() > 0 ? Active::Bonded : Active::Gap;
    else if (!law.normal_active()) statuses[k] = Active::Gap;
    else statuses[k] = law.tangential_active() ? Active::Stick : Active::Frictionless;
  }
  return statuses;
}

namespace {

// d = B u + g_D + C r of an answer.
Eigen::VectorXd jump_part(const ContactProblem& problem, const MixedSystem::Answer& a) {
  Eigen::VectorXd d = problem.jumps(a.u);
  for (int i = 0; i < d.size(); ++i)
    if (std::isfinite(problem.compliance()[i])) d[i] += problem.compliance()[i] * a.r[i];
  return d;
}

StopCause stop_cause(const SparseNewtonRun& run, bool capped) {
  const SolveReport& r = run.report;
  if (!std::isfinite(r.residual.value())) return run.singular ? StopCause::Singular : StopCause::NonFinite;
  if (r.residual.value() <= r.tolerance) return StopCause::Converged;
  if (r.residual.value() <= r.residual.floor()) return StopCause::RoundOffFloor;
  if (run.singular) return StopCause::Singular;
  if (run.settled) return StopCause::LossOfAccuracy;
  return capped || run.cycled ? StopCause::IterationCap : StopCause::LossOfAccuracy;
}

}  // namespace

SparseNewtonRun solve_sparse_newton(const ContactProblem& problem, const SolverOptions& options,
                                    std::vector<Active> seed, int max_steps) {
  const auto start = std::chrono::steady_clock::now();
  SparseNewtonRun run;
  SolveReport& best = run.report;
  best.solver = "fast";
  best.method = "sparse Newton";
  best.tolerance = options.tolerance;
  best.residual.interface = best.residual.bulk = std::numeric_limits<double>::infinity();
  MixedSystem mixed(problem);
  // κ_i: the row's stiffness with everything else held (MixedSystem::row_stiffness). Its size
  // decides only where a row both carries a force and opens or slips the wrong way; the statuses
  // of an exact Newton step have r = 0 or d = 0 on each row.
  const Condensed rules = law_rules(problem, mixed.row_stiffness());
  std::vector<Active> statuses = seed.empty() ? stuck_statuses(problem) : std::move(seed);
  std::set<std::vector<Active>> seen{statuses};
  int steps = 0;
  for (; steps < max_steps; ++steps) {
    const MixedSystem::Answer a = mixed.solve(statuses);
    if (a.singular || !a.u.allFinite() || !a.r.allFinite()) {
      run.singular = true;
      break;
    }
    const Residual residual = contact_residual(problem, a.u, a.r, a.band_z);
    if (options.verbose)
      std::fprintf(stderr, "  sparse Newton: step %d, residual %.3e\n", steps + 1, residual.value());
    if (residual.value() < best.residual.value()) {
      best.u = a.u;
      best.r = a.r;
      best.residual = residual;
      best.condition_estimate = 1.0 / std::max(a.rcond, 1e-300);
    }
    if (residual.value() <= options.tolerance) {
      ++steps;
      break;
    }
    std::vector<Active> next = guess_statuses(rules, a.r, jump_part(problem, a));
    if (next == statuses) {  // the statuses' own answer, and still above the tolerance
      run.settled = true;
      ++steps;
      break;
    }
    if (!seen.insert(next).second) {
      run.cycled = true;
      ++steps;
      break;
    }
    statuses = std::move(next);
  }
  best.iterations = steps;
  best.stop_cause = stop_cause(run, steps >= max_steps);
  best.converged = best.stop_cause == StopCause::Converged;
  best.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (best.converged ? "converged" : "NOT converged") << " after " << steps
      << " semismooth Newton steps on the whole sparse system from the bonded solve, residual " << best.residual.value()
      << " (tolerance " << options.tolerance << ")";
  if (!best.converged) msg << ": " << to_string(best.stop_cause) << (run.cycled ? " (a status set came back)" : "");
  best.message = msg.str();
  return run;
}

}  // namespace thinlayer
