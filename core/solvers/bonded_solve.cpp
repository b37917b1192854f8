#include "core/solvers/bonded_solve.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "core/solvers/mixed_system.h"

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

namespace {

StopCause stop_cause(const MixedSystem::Answer& answer, const SolveReport& report) {
  if (!report.u.allFinite() || !report.r.allFinite() || !std::isfinite(report.residual.value()))
    return StopCause::NonFinite;
  if (answer.singular) return StopCause::Singular;
  if (report.residual.value() <= report.tolerance) return StopCause::Converged;
  // The residual is the answer's own (extended precision): within the floor, rounding it to double
  // accounts for all of it; above, the LU itself fell short (its condition estimate says how far).
  return report.residual.value() <= report.residual.floor() ? StopCause::RoundOffFloor : StopCause::LossOfAccuracy;
}

}  // namespace

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
  const MixedSystem::Answer answer = mixed.solve(bonded_statuses(problem));
  report.iterations = 1;
  report.u = answer.u;
  report.r = answer.r;
  report.residual = contact_residual(problem, answer.u, answer.r, answer.band_z);
  report.condition_estimate = 1.0 / std::max(answer.rcond, 1e-300);
  report.stop_cause = stop_cause(answer, report);
  report.converged = report.stop_cause == StopCause::Converged;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream msg;
  msg << (report.converged ? "converged" : "NOT converged")
      << ": every face bonded, one sparse solve of the whole system, residual " << report.residual.value()
      << " (tolerance " << options.tolerance << ")";
  if (!report.converged) msg << ": " << to_string(report.stop_cause) << "; condition estimate " << report.condition_estimate;
  else if (report.condition_estimate > 1e12)
    msg << "; ill-conditioned: condition estimate " << report.condition_estimate;
  report.message = msg.str();
  return report;
}

}  // namespace thinlayer
