#include "core/solvers/bonded_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/solvers/mixed_system.h"
#include "core/solvers/stop_verdict.h"

namespace thinlayer {

bool every_interface_bonded(const ContactProblem& problem) {
  const std::vector<Interface>& interfaces = problem.interfaces();
  return !interfaces.empty() &&
         std::all_of(interfaces.begin(), interfaces.end(), [](const Interface& i) { return i.law.bilateral; });
}

std::vector<Active> bonded_statuses(const ContactProblem& problem) {
  std::vector<Active> statuses(problem.num_nodes());
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceLaw& law = problem.law(k);
    statuses[k] = law.normal_active() || law.K_T() > 0 ? Active::Bonded : Active::Gap;
  }
  return statuses;
}

SolveReport solve_bonded(const ContactProblem& problem, const SolverOptions& options, MixedSystem* factored) {
  if (!every_interface_bonded(problem))
    throw std::invalid_argument("solve_bonded: an interface of this problem is not bonded (its law is unilateral)");
  const auto start = std::chrono::steady_clock::now();
  SolveReport report;
  report.solver = "fast";
  report.method = "bonded solve";
  report.tolerance = options.tolerance;
  if (factored && &factored->problem() != &problem)
    throw std::invalid_argument("solve_bonded: the MixedSystem given was built on another problem");
  std::unique_ptr<MixedSystem> local;
  if (!factored) local = std::make_unique<MixedSystem>(problem);
  MixedSystem& mixed = factored ? *factored : *local;
  mixed.prove_round_off(true);  // the verdict's floor needs it
  const MixedSystem::Answer answer = mixed.solve(bonded_statuses(problem));
  report.iterations = 1;
  report.u = answer.u;
  report.r = answer.r;
  report.residual = contact_residual(problem, answer.u, answer.r, answer.band_z);
  // The verdict (core/solvers/stop_verdict.h) on this one linear system: its answer refined to its
  // last digit (SparseLU::solve), its condition bounded below and what it nearly leaves free.
  LinearEvidence evidence;
  evidence.linear = true;
  evidence.factor_failed = answer.singular;
  evidence.at_round_off = answer.at_round_off;
  const MixedSystem::NearNull near = mixed.near_null();
  evidence.condition = near.condition;
  evidence.free_motion = near.u;
  report.condition_estimate = near.condition;
  const StopVerdict verdict = stop_verdict(problem, answer.u, answer.r, report.residual, options.tolerance, evidence);
  report.stop_cause = verdict.cause;
  report.converged = verdict.converged;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (report.converged ? "converged" : "NOT converged")
      << ": every face bonded, one sparse solve of the whole system, residual " << report.residual.value()
      << " (tolerance " << options.tolerance << ")";
  if (!report.converged) msg << ": " << verdict.why;
  report.message = msg.str();
  return report;
}

}  // namespace thinlayer
