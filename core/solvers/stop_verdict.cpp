#include "core/solvers/stop_verdict.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

namespace thinlayer {

namespace {

std::string number(double x, int digits = 3) {
  std::ostringstream s;
  s.precision(digits);
  s << x;
  return s.str();
}

// The interfaces touching body b whose law has no stiffness in a direction, in words.
std::string free_laws(const ContactProblem& problem, int body) {
  std::set<int> seen;
  std::string s;
  for (int k = 0; k < problem.num_nodes(); ++k) {
    const InterfaceNode& n = problem.node(k);
    if (body >= 0 && n.plus_body != body && n.minus_body != body) continue;
    const int i = problem.interface_of(k);
    if (!seen.insert(i).second) continue;
    const InterfaceLaw& law = problem.law(k);
    std::string gap;
    if (!(law.K_N() > 0)) gap = "no normal stiffness (K_N = 0)";
    else if (!(law.K_T() > 0)) gap = "no shear stiffness (mu_bar = 0)";
    else if (!law.bilateral && !(law.friction > 0)) gap = "no shear (contact without friction)";
    if (!gap.empty()) s += (s.empty() ? "" : "; ") + problem.interfaces()[i].name + "'s law has " + gap;
  }
  return s;
}

}  // namespace

std::string free_part(const ContactProblem& problem, const Eigen::VectorXd& free_motion) {
  const LinearSystem& system = problem.system();
  std::ostringstream s;
  if (free_motion.size() == system.num_free() && free_motion.allFinite() && free_motion.squaredNorm() > 0) {
    std::vector<double> share(system.num_bodies(), 0.0);
    std::vector<Eigen::Vector2d> mean(system.num_bodies(), Eigen::Vector2d::Zero());
    std::vector<int> count(system.num_bodies(), 0);
    for (int i = 0; i < system.num_free(); ++i) share[system.body_of(i)] += free_motion[i] * free_motion[i];
    const double total = free_motion.squaredNorm();
    const int body = static_cast<int>(std::max_element(share.begin(), share.end()) - share.begin());
    s << "its near-null motion moves body '" << system.body_name(body) << "' (" << number(100 * share[body] / total)
      << " % of it)";
    const std::string laws = free_laws(problem, body);
    s << (laws.empty() ? "" : ": " + laws);
    return s.str();
  }
  const std::string laws = free_laws(problem, -1);
  return laws.empty() ? "the body or law that leaves it free is not identified" : laws;
}

StopVerdict stop_verdict(const ContactProblem& problem, const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                         const Residual& residual, double tolerance, const LinearEvidence& e,
                         StopCause iteration_cause) {
  StopVerdict v;
  const double value = residual.value();
  if (!u.allFinite() || !r.allFinite() || !std::isfinite(value)) {
    v.cause = StopCause::NonFinite;
    v.why = "NaN or Inf in the answer";
    return v;
  }
  const bool ill = e.factor_failed || e.condition > singular_condition;
  const bool singular = ill || (e.linear && value > singular_residual);
  if (singular && (e.linear || value > tolerance)) {
    v.cause = StopCause::Singular;
    std::ostringstream s;
    s << (e.factor_failed ? "singular system (its factorisation failed)"
          : ill           ? "near-singular system (condition at least " + number(e.condition) + ", beyond " +
                                number(singular_condition) + ")"
                          : "singular system (residual " + number(value) + " after refinement, above " +
                                number(singular_residual) + ")")
      << ": " << free_part(problem, e.free_motion) << "; its numbers are not used";
    v.why = s.str();
    return v;
  }
  if (value <= tolerance) {
    v.cause = StopCause::Converged;
    v.converged = v.usable = true;
    return v;
  }
  std::ostringstream s;
  if (e.linear && e.at_round_off && value <= residual.floor()) {
    v.cause = StopCause::RoundOffFloor;
    v.usable = true;
    s << "round-off floor, proven: the answer is its linear system's exact solution to double's rounding (refined "
         "with extended-precision residuals until a correction was below the last digit of its largest unknown), and its "
         "residual, evaluated in extended precision, "
      << number(value) << ", is within what rounding it to double moves it by (" << number(residual.floor()) << ")";
  } else if (e.linear) {
    v.cause = StopCause::LossOfAccuracy;
    s << "loss of accuracy: the linear solve stops at " << number(value)
      << (e.at_round_off ? ", above what rounding its answer to double moves the residual by (" + number(residual.floor()) + ")"
                         : ", its refinement still changing the answer (no floor shown)");
  } else {
    // The solver's iteration stopped first; a floor it may not claim without the proof above.
    v.cause = iteration_cause == StopCause::RoundOffFloor || iteration_cause == StopCause::Converged
                  ? StopCause::LossOfAccuracy
                  : iteration_cause;
    s << to_string(v.cause);
  }
  if (e.condition > 0) s << (e.linear ? "; condition at least " : "; condition estimate ") << number(e.condition);
  v.why = s.str();
  return v;
}

bool usable(const SolveReport& report) {
  return report.converged || report.stop_cause == StopCause::RoundOffFloor;
}

}  // namespace thinlayer
